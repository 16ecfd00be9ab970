//! The Bernstein polynomials B_{i,n}(t) and their derivatives.
