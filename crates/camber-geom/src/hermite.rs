//! Cubic Hermite (parametric cubic) curves.
