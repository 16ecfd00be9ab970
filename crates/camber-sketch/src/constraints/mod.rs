//! The constraint kinds: one module per kind, each a struct with named fields implementing
//! [`ConstraintKind`], and the [`Constraint`] enum generated once from the list below.
//!
//! A kind's module holds everything about it: the entities it reads, its validation and its
//! rows ([`ConstraintKind::compile`], through the generic [`camber_solve::Residual`], affine or
//! not), the checks of a solved state it needs ([`crate::component::SolvedCheck`]), its file
//! form (the struct's serde derive, under the tag [`ConstraintKind::TAG`]), its glyph
//! ([`ConstraintKind::glyphs`]) and its part in iterative displacement
//! ([`ConstraintKind::contact`]). User kinds go through the same path as [`Custom`].
//!
//! **Adding a kind** is one new module here and one line in the `kinds!` list: the enum
//! variant, the conversions, the dispatch of every method, the file form and the list of tags
//! are generated from it, and no match anywhere has a wildcard arm that could hide a kind.
//!
//! ```
//! use camber_sketch::constraints::{Coincident, Horizontal};
//! use camber_sketch::{Constraint, PointRef, Sketch};
//! use nalgebra::Point2;
//! let mut s = Sketch::new();
//! let (a, b) = (s.add_line(Point2::new(0.0, 0.0), Point2::new(1.0, 0.2))?, s.add_line(Point2::new(1.0, 0.2), Point2::new(1.5, 1.0))?);
//! s.add_constraint(Horizontal::line(a))?;
//! s.add_constraint(Coincident { a: PointRef::End(a), b: PointRef::Start(b) })?;
//! s.solve()?;
//! let (p, q) = (s.point(PointRef::Start(a))?, s.point(PointRef::End(a))?);
//! assert!((p.y - q.y).abs() < 1e-12);
//! assert_eq!(s.constraints().next().map(|(_, c)| c.tag()), Some("horizontal"));
//! # Ok::<(), camber_sketch::Error>(())
//! ```

use serde_json::Value;
use smallvec::SmallVec;

use crate::constraints::check::ContactSpec;
use crate::constraints::piece::Pieces;
use crate::ground::errors::Result;
use crate::ground::ids::{ConstraintId, EntityId};
use crate::ground::lookup::EntityLookup;

pub mod check;
pub mod compiler;
pub mod glyph;
pub(crate) mod piece;
pub(crate) mod shared;

pub use compiler::Compiler;
pub use glyph::Glyph;

/// What every constraint kind provides (see the module documentation).
pub trait ConstraintKind:
    std::fmt::Debug + Clone + PartialEq + serde::Serialize + serde::de::DeserializeOwned
{
    /// The kind's word in sketch files and the CLI ("tangent_to_circle").
    const TAG: &'static str;
    /// The kind in plain words, as reports name it ("tangent to circle").
    const LABEL: &'static str;

    /// Adds every entity the constraint reads (its edges in the sketch graph).
    fn entities(&self, out: &mut Entities);

    /// Validates the constraint against the entities and writes its rows.
    ///
    /// # Errors
    /// What is wrong with it: an unknown id, an entity of the wrong kind, a parameter outside
    /// a domain, a non-finite or non-positive number, a zero direction.
    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()>;

    /// Its marks in a picture, on the geometry `at` shows.
    ///
    /// # Errors
    /// A reference `at` cannot resolve (not for a constraint the sketch accepted).
    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>>;

    /// Stores the solved value of its `k`-th free parameter (a contact parameter).
    fn set_free_parameter(&mut self, k: usize, value: f64) {
        let _ = (k, value);
    }

    /// The contact it makes with a circle or a line, for honest contact and iterative
    /// displacement.
    fn contact(&self) -> Option<ContactSpec> {
        None
    }

    /// Other constraints it reads (their free parameters); they must stay in the sketch.
    fn reads_constraints(&self) -> SmallVec<[ConstraintId; 2]> {
        SmallVec::new()
    }

    /// Its value, when it is a dimension (a distance, a radius, an angle, an arc length, …):
    /// the number [`crate::Sketch::set_value`] changes. `None` for a kind without one.
    fn value(&self) -> Option<f64> {
        None
    }

    /// Sets its value (see [`ConstraintKind::value`]); `false`, changing nothing, for a kind
    /// without one. The new value is validated when the sketch compiles the constraint.
    fn set_value(&mut self, value: f64) -> bool {
        let _ = value;
        false
    }

    /// The field of its file form that holds its value (see [`ConstraintKind::value`]):
    /// `"distance"`, `"radius"`, … `None` for a kind without one.
    fn value_field(&self) -> Option<&'static str> {
        None
    }
}

/// The entities a constraint reads, each once.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Entities(SmallVec<[EntityId; 4]>);

impl Entities {
    /// Adds an entity (a repeat is ignored).
    pub fn add(&mut self, id: EntityId) {
        if !self.0.contains(&id) {
            self.0.push(id);
        }
    }

    /// Adds the entity of a point reference.
    pub fn add_point(&mut self, r: crate::ground::ids::PointRef) {
        self.add(r.entity());
    }
}

/// Why a constraint's file form could not be read: the JSON path inside the constraint and
/// what is wrong there.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct FormError {
    pub(crate) path: String,
    pub(crate) message: String,
}

/// `{"kind": TAG, …fields}` for a kind's struct.
#[derive(serde::Serialize)]
struct Tagged<'a, T> {
    kind: &'static str,
    #[serde(flatten)]
    body: &'a T,
}

fn save<K: ConstraintKind>(c: &K) -> serde_json::Result<String> {
    serde_json::to_string(&Tagged {
        kind: K::TAG,
        body: c,
    })
}

fn load<K: ConstraintKind>(mut value: Value) -> std::result::Result<K, FormError> {
    if let Value::Object(map) = &mut value {
        map.remove("kind");
    }
    serde_path_to_error::deserialize::<_, K>(value).map_err(|e| FormError {
        path: e.path().to_string(),
        message: e.inner().to_string(),
    })
}

macro_rules! kinds {
    ($( $(#[$doc:meta])* $variant:ident => $module:ident :: $kind:ident ),* $(,)?) => {
        $(pub mod $module;)*
        $(pub use $module::$kind;)*

        /// A constraint of a sketch: one of the built-in kinds, each in its own module of
        /// [`crate::constraints`], or a user's [`Custom`] kind.
        ///
        /// Every kind converts into it (`s.add_constraint(Horizontal::line(l))`), and it is
        /// matched as `Constraint::Horizontal(h)`.
        #[derive(Debug, Clone, PartialEq)]
        #[non_exhaustive]
        pub enum Constraint {
            $( $(#[$doc])* $variant($kind), )*
        }

        $(
            impl From<$kind> for Constraint {
                fn from(c: $kind) -> Self {
                    Constraint::$variant(c)
                }
            }
        )*

        impl Constraint {
            /// Every kind's file tag, in the order of the list of kinds.
            pub const TAGS: &'static [&'static str] = &[$(<$kind as ConstraintKind>::TAG),*];

            /// The kind's word in sketch files ("tangent_to_circle").
            pub fn tag(&self) -> &'static str {
                match self {
                    $(Constraint::$variant(_) => <$kind as ConstraintKind>::TAG,)*
                }
            }

            /// The kind in plain words, as reports name it ("tangent to circle").
            pub fn kind_name(&self) -> &'static str {
                match self {
                    $(Constraint::$variant(_) => <$kind as ConstraintKind>::LABEL,)*
                }
            }

            /// The entities the constraint reads (its edges in the sketch graph), without
            /// repeats.
            pub fn entities(&self) -> SmallVec<[EntityId; 4]> {
                let mut out = Entities::default();
                match self {
                    $(Constraint::$variant(c) => c.entities(&mut out),)*
                }
                out.0
            }

            /// Its marks in a picture, on the geometry `at` shows (a sketch, or a view of it
            /// with some entities replaced).
            ///
            /// # Errors
            /// A reference `at` cannot resolve.
            pub fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
                match self {
                    $(Constraint::$variant(c) => c.glyphs(at),)*
                }
            }

            /// The contact it makes with a circle or a line, if it is one.
            pub fn contact(&self) -> Option<ContactSpec> {
                match self {
                    $(Constraint::$variant(c) => c.contact(),)*
                }
            }

            /// Validates against the entities of `lookup` and compiles to pieces.
            pub(crate) fn compile(&self, lookup: &dyn EntityLookup) -> Result<Pieces> {
                Ok(self.compile_tracked(lookup)?.0)
            }

            /// [`Constraint::compile`], also saying whether the pieces depend on the
            /// entities' current values ([`Compiler`]).
            pub(crate) fn compile_tracked(&self, lookup: &dyn EntityLookup) -> Result<(Pieces, bool)> {
                let mut cx = Compiler::new(lookup);
                match self {
                    $(Constraint::$variant(c) => c.compile(&mut cx)?,)*
                }
                Ok(cx.finish())
            }

            /// Stores the solved value of its `k`-th free parameter.
            pub(crate) fn set_free_parameter(&mut self, k: usize, value: f64) {
                match self {
                    $(Constraint::$variant(c) => c.set_free_parameter(k, value),)*
                }
            }

            /// Its value, when it is a dimension (a distance, a radius, an angle, an arc
            /// length, …).
            pub fn value(&self) -> Option<f64> {
                match self {
                    $(Constraint::$variant(c) => c.value(),)*
                }
            }

            /// The field of its file form holding its value (`"distance"`, `"radius"`, …),
            /// the path [`crate::Sketch::bind_dimension`] takes for it; `None` for a kind
            /// without a value.
            pub fn value_field(&self) -> Option<&'static str> {
                match self {
                    $(Constraint::$variant(c) => c.value_field(),)*
                }
            }

            /// Sets a dimension's value; `false`, changing nothing, for a kind without one.
            pub(crate) fn set_value(&mut self, value: f64) -> bool {
                match self {
                    $(Constraint::$variant(c) => c.set_value(value),)*
                }
            }

            /// Other constraints it reads.
            pub(crate) fn reads_constraints(&self) -> SmallVec<[ConstraintId; 2]> {
                match self {
                    $(Constraint::$variant(c) => c.reads_constraints(),)*
                }
            }

            /// The file form: `{"kind": tag, …fields}` (without the id).
            pub(crate) fn save(&self) -> serde_json::Result<String> {
                match self {
                    $(Constraint::$variant(c) => save(c),)*
                }
            }

            /// Reads the file form of the kind `tag` (`None` for an unknown tag).
            pub(crate) fn load(
                tag: &str,
                value: Value,
            ) -> Option<std::result::Result<Constraint, FormError>> {
                $(
                    if tag == <$kind as ConstraintKind>::TAG {
                        return Some(load::<$kind>(value).map(Constraint::$variant));
                    }
                )*
                None
            }
        }
    };
}

kinds! {
    /// The target does not move.
    Fixed => fixed::Fixed,
    /// Two points coincide (two affine rows, or one merged unknown).
    Coincident => coincident::Coincident,
    /// C(u) = target (two affine rows).
    PointAtParameter => point_at_parameter::PointAtParameter,
    /// C′(u) = vector (two affine rows).
    TangentVectorAt => tangent_vector_at::TangentVectorAt,
    /// C′(u) parallel to a fixed direction (one affine row).
    DirectionalTangentAt => directional_tangent_at::DirectionalTangentAt,
    /// The start tangent parallel to a fixed direction (row or elimination form).
    StartTangent => start_tangent::StartTangent,
    /// The end tangent parallel to a fixed direction (row or elimination form).
    EndTangent => end_tangent::EndTangent,
    /// C(u) on a fixed line and C′(u) along it (two affine rows).
    TangentToLineAt => tangent_to_line_at::TangentToLineAt,
    /// Two curves joined G1 along a fixed direction (four affine rows).
    G1Join => g1_join::G1Join,
    /// A user-written residual over any unknowns of the sketch.
    Custom => custom::Custom,
    /// A point on a curve, at a fixed or free parameter.
    PointOnCurve => point_on_curve::PointOnCurve,
    /// A curve touching a line entity.
    TangentToLine => tangent_to_line::TangentToLine,
    /// A curve touching a circle entity.
    TangentToCircle => tangent_to_circle::TangentToCircle,
    /// A point on a circle entity.
    PointOnCircle => point_on_circle::PointOnCircle,
    /// A circle's radius.
    Radius => radius::Radius,
    /// Two points a distance apart.
    Distance => distance::Distance,
    /// Two lines parallel.
    Parallel => parallel::Parallel,
    /// Two lines perpendicular.
    Perpendicular => perpendicular::Perpendicular,
    /// The angle from one line to another.
    Angle => angle::Angle,
    /// Two curves joined G2 (free direction).
    G2Join => g2_join::G2Join,
    /// Two curves touching at fixed or free parameters.
    CurveCurveTangent => curve_curve_tangent::CurveCurveTangent,
    /// Two curves joined G1 with a free direction.
    G1JoinFree => g1_join_free::G1JoinFree,
    /// A line or two points level (one affine row).
    Horizontal => horizontal::Horizontal,
    /// A line or two points plumb (one affine row).
    Vertical => vertical::Vertical,
    /// Two segments equally long.
    EqualLength => equal_length::EqualLength,
    /// Two circles of equal radius (one affine row).
    EqualRadius => equal_radius::EqualRadius,
    /// Two circles with one centre (two affine rows).
    Concentric => concentric::Concentric,
    /// A point on the infinite line of a line entity.
    PointOnLine => point_on_line::PointOnLine,
    /// A point at a distance from the infinite line of a line entity.
    PointLineDistance => point_line_distance::PointLineDistance,
    /// A point at the middle of a line or two points (two affine rows).
    Midpoint => midpoint::Midpoint,
    /// Two points mirrored in a line.
    Symmetric => symmetric::Symmetric,
    /// A horizontal offset between two points (one affine row).
    HorizontalDistance => horizontal_distance::HorizontalDistance,
    /// A vertical offset between two points (one affine row).
    VerticalDistance => vertical_distance::VerticalDistance,
    /// A curve's arc length.
    ArcLength => arc_length::ArcLength,
    /// A curve's signed curvature at a parameter.
    CurvatureAt => curvature_at::CurvatureAt,
    /// Two curves joined with equal first derivatives (four affine rows).
    C1Join => c1_join::C1Join,
    /// Two curves joined with equal first and second derivatives (six affine rows).
    C2Join => c2_join::C2Join,
    /// Rows written as text over named sketch quantities (affine when the tape says so).
    Expression => expression::Expression,
    /// A point on an arc (its circle, within its sweep).
    PointOnArc => point_on_arc::PointOnArc,
    /// An arc's tangent at one end along a line entity.
    ArcTangentToLine => arc_tangent_to_line::ArcTangentToLine,
    /// An arc's travel at one end along a curve's tangent at one of its ends.
    ArcTangentToCurve => arc_tangent_to_curve::ArcTangentToCurve,
    /// A point on an ellipse or an elliptic arc (within its sweep).
    PointOnEllipse => point_on_ellipse::PointOnEllipse,
    /// One semi-axis of an ellipse or elliptic arc.
    SemiAxis => semi_axis::SemiAxis,
    /// An elliptic arc's tangent at one end along a line entity.
    EllipticArcTangentToLine => elliptic_arc_tangent_to_line::EllipticArcTangentToLine,
    /// An elliptic arc's travel at one end along a curve's tangent at one of its ends.
    EllipticArcTangentToCurve => elliptic_arc_tangent_to_curve::EllipticArcTangentToCurve,
    /// An arc's travel at one end along another arc's end, or along a circle.
    ArcTangentToArc => arc_tangent_to_arc::ArcTangentToArc,
    /// An arc touching a line's infinite line in its interior, on a recorded side.
    ArcTouchesLine => arc_touches_line::ArcTouchesLine,
    /// An arc touching a circle or another arc's circle in its interior, externally or
    /// internally.
    ArcTouchesCircle => arc_touches_circle::ArcTouchesCircle,
    /// The sweep of a circular or an elliptic arc.
    ArcAngle => arc_angle::ArcAngle,
    /// A curve's curvature at one of its ends matching an arc's at one of its ends.
    ArcCurvatureToCurve => arc_curvature_to_curve::ArcCurvatureToCurve,
    /// An ellipse or elliptic arc touching a line's infinite line in its interior, on a
    /// recorded side.
    EllipseTouchesLine => ellipse_touches_line::EllipseTouchesLine,
    /// Two circles or arcs, in either order, touching externally or internally.
    CircleTouchesCircle => circle_touches_circle::CircleTouchesCircle,
    /// An ellipse or elliptic arc touching a circle or arc at a free parametric angle,
    /// externally or internally.
    EllipseTouchesCircle => ellipse_touches_circle::EllipseTouchesCircle,
    /// A curve touching an ellipse or elliptic arc in its interior, at a free parametric
    /// angle.
    TangentToEllipse => tangent_to_ellipse::TangentToEllipse,
}
