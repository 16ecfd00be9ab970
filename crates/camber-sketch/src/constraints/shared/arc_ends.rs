//! The ends of circular and elliptic arcs, as the arc kinds name them.

use serde::{Deserialize, Serialize};

use crate::ground::ids::{EntityId, PointRef};

/// Which end of an arc: `"start"` or `"end"`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ArcEnd {
    /// The start (block 1).
    Start,
    /// The end (block 2).
    End,
}

impl ArcEnd {
    /// The arc's point block of this end.
    pub fn block(self) -> usize {
        match self {
            ArcEnd::Start => 1,
            ArcEnd::End => 2,
        }
    }

    /// The end as a point reference of `arc`.
    pub fn point(self, arc: EntityId) -> PointRef {
        match self {
            ArcEnd::Start => PointRef::Start(arc),
            ArcEnd::End => PointRef::End(arc),
        }
    }
}
