//! Composite curves and joint continuity reports.
