//! NURBS (rational B-spline) curves.
