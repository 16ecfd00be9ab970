//! Helpers that sibling kinds share: what two or more kinds compute the same way lives here,
//! never in one kind's file for the others to borrow.
//!
//! - [`arc_ends`]: the ends of circular and elliptic arcs, and the sense check of an arc end held
//!   tangent to a curve end;
//! - [`arc_span`]: whether a direction from an arc's centre lies within its sweep;
//! - [`angles`]: the signed angle between two tangents and the angle of a line;
//! - [`axes`]: rows and marks along a coordinate axis (horizontal, vertical, their distances,
//!   equal lengths);
//! - [`joins`]: the joints between curve ends (C1/C2 parametric joins, G1/G2 bases and the
//!   tangents-parallel check, the tangency of an end);
//! - [`lines`]: the signed offset of a point from a line;
//! - [`ellipses`]: the kind check, end blocks and travel of ellipses and elliptic arcs;
//! - [`radii`]: the radius and centre of a circle or an arc;
//! - [`round_contacts`]: where two circles or arcs touch, and the check that it is on the arcs;
//! - [`sweeps`]: the sweep of a circular or elliptic arc and the arc lengths over it.

pub(crate) mod angles;
pub(crate) mod arc_ends;
pub(crate) mod arc_span;
pub(crate) mod axes;
pub(crate) mod ellipses;
pub(crate) mod joins;
pub(crate) mod lines;
pub(crate) mod radii;
pub(crate) mod round_contacts;
pub(crate) mod sweeps;
