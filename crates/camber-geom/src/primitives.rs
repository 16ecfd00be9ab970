//! Points, lines, segments and circles.
