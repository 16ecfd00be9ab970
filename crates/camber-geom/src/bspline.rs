//! Non-rational B-spline curves.
