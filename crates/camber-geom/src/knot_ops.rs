//! Knot insertion, refinement, Bézier decomposition and degree elevation on control nets.
