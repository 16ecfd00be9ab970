//! The small leaf types of the file form: point references, fix targets, contact parameters,
//! and the sense, side, rotation and tangent-form words, with their conversions both ways.

use serde::{Deserialize, Serialize};

use super::raw::Xy;
use crate::constraint::{CircleSide, Contact, LineSide, Rotation, Sense, TangentForm};
use crate::ids::{EntityId, PointRef};

/// A point reference: `{"point": 3}`, `{"control": [3, 1]}`, `{"start": 3}`, `{"end": 3}`.
#[derive(Serialize, Deserialize, Clone, Copy)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub(super) enum RawPoint {
    Point(u64),
    Control(u64, usize),
    Start(u64),
    End(u64),
}

impl From<RawPoint> for PointRef {
    fn from(p: RawPoint) -> Self {
        match p {
            RawPoint::Point(e) => PointRef::Point(EntityId(e)),
            RawPoint::Control(e, i) => PointRef::Control(EntityId(e), i),
            RawPoint::Start(e) => PointRef::Start(EntityId(e)),
            RawPoint::End(e) => PointRef::End(EntityId(e)),
        }
    }
}

impl From<PointRef> for RawPoint {
    fn from(p: PointRef) -> Self {
        match p {
            PointRef::Point(e) => RawPoint::Point(e.0),
            PointRef::Control(e, i) => RawPoint::Control(e.0, i),
            PointRef::Start(e) => RawPoint::Start(e.0),
            PointRef::End(e) => RawPoint::End(e.0),
        }
    }
}

#[derive(Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub(super) enum RawFix {
    Entity(u64),
    Point(RawPoint),
}

#[derive(Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub(super) enum RawTarget {
    At(Xy),
    Point(RawPoint),
}

#[derive(Serialize, Deserialize, Clone, Copy, Default)]
#[serde(rename_all = "snake_case")]
pub(super) enum RawSense {
    #[default]
    Agree,
    Oppose,
}

#[derive(Serialize, Deserialize, Clone, Copy, Default)]
#[serde(rename_all = "snake_case")]
pub(super) enum RawForm {
    #[default]
    Row,
    Elimination,
}

impl From<RawSense> for Sense {
    fn from(s: RawSense) -> Self {
        match s {
            RawSense::Agree => Sense::Agree,
            RawSense::Oppose => Sense::Oppose,
        }
    }
}

impl From<Sense> for RawSense {
    fn from(s: Sense) -> Self {
        match s {
            Sense::Agree => RawSense::Agree,
            Sense::Oppose => RawSense::Oppose,
        }
    }
}

impl From<RawForm> for TangentForm {
    fn from(s: RawForm) -> Self {
        match s {
            RawForm::Row => TangentForm::Row,
            RawForm::Elimination => TangentForm::Elimination,
        }
    }
}

impl From<TangentForm> for RawForm {
    fn from(s: TangentForm) -> Self {
        match s {
            TangentForm::Row => RawForm::Row,
            TangentForm::Elimination => RawForm::Elimination,
        }
    }
}

/// A contact parameter: `{"at": 0.3}` (fixed) or `{"free": 0.3}` (an unknown starting there).
#[derive(Serialize, Deserialize, Clone, Copy)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub(super) enum RawContact {
    At(f64),
    Free(f64),
}

impl From<RawContact> for Contact {
    fn from(c: RawContact) -> Self {
        match c {
            RawContact::At(u) => Contact::At(u),
            RawContact::Free(u) => Contact::Free(u),
        }
    }
}

impl From<Contact> for RawContact {
    fn from(c: Contact) -> Self {
        match c {
            Contact::At(u) => RawContact::At(u),
            Contact::Free(u) => RawContact::Free(u),
        }
    }
}

#[derive(Serialize, Deserialize, Clone, Copy)]
#[serde(rename_all = "snake_case")]
pub(super) enum RawLineSide {
    Left,
    Right,
}

#[derive(Serialize, Deserialize, Clone, Copy)]
#[serde(rename_all = "snake_case")]
pub(super) enum RawCircleSide {
    Outside,
    Inside,
}

#[derive(Serialize, Deserialize, Clone, Copy)]
#[serde(rename_all = "snake_case")]
pub(super) enum RawRotation {
    CounterClockwise,
    Clockwise,
}

impl From<RawLineSide> for LineSide {
    fn from(s: RawLineSide) -> Self {
        match s {
            RawLineSide::Left => LineSide::Left,
            RawLineSide::Right => LineSide::Right,
        }
    }
}

impl From<LineSide> for RawLineSide {
    fn from(s: LineSide) -> Self {
        match s {
            LineSide::Left => RawLineSide::Left,
            LineSide::Right => RawLineSide::Right,
        }
    }
}

impl From<RawCircleSide> for CircleSide {
    fn from(s: RawCircleSide) -> Self {
        match s {
            RawCircleSide::Outside => CircleSide::Outside,
            RawCircleSide::Inside => CircleSide::Inside,
        }
    }
}

impl From<CircleSide> for RawCircleSide {
    fn from(s: CircleSide) -> Self {
        match s {
            CircleSide::Outside => RawCircleSide::Outside,
            CircleSide::Inside => RawCircleSide::Inside,
        }
    }
}

impl From<RawRotation> for Rotation {
    fn from(s: RawRotation) -> Self {
        match s {
            RawRotation::CounterClockwise => Rotation::CounterClockwise,
            RawRotation::Clockwise => Rotation::Clockwise,
        }
    }
}

impl From<Rotation> for RawRotation {
    fn from(s: Rotation) -> Self {
        match s {
            Rotation::CounterClockwise => RawRotation::CounterClockwise,
            Rotation::Clockwise => RawRotation::Clockwise,
        }
    }
}
