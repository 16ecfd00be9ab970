//! Curve queries: curvature, closest point, intersections, minimum distance.
