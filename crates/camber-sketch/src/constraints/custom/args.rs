//! The arguments of a custom constraint: what each reads ([`Arg`]), where each sits among the
//! blocks of one build (`Layout`), and the typed view a residual reads them through ([`Args`],
//! [`CurveArg`]).

use camber_solve::scalar::cst;
use camber_solve::{ConstraintId, Scalar};
use serde::{Deserialize, Serialize};

use crate::ground::curve_eval::CurveBasis;
use crate::ground::ids::{EntityId, PointRef};
pub use crate::ground::vocabulary::ArgKind;

/// One argument of a custom constraint: what its residual reads.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum Arg {
    /// A point: a point entity, a control point, a line end, a circle centre, or the end of a
    /// curve clamped there (a block of two: x, y).
    Point(PointRef),
    /// The radius of a circle entity (a block of one).
    Radius(EntityId),
    /// A whole curve: its control points (a block of two each), evaluated with the curve's
    /// degree, knots and weights as they are when the component is built.
    Curve(EntityId),
    /// The `index`-th free parameter of another constraint (a free contact parameter; a block
    /// of one).
    FreeOf(u64, usize),
    /// A free parameter of the constraint's own, starting at this value (a block of one); a
    /// successful solve stores the solved value here.
    Param(f64),
}

impl Arg {
    /// The kind of value the argument gives the residual.
    pub fn kind(&self) -> ArgKind {
        match self {
            Arg::Point(_) => ArgKind::Point,
            Arg::Radius(_) | Arg::FreeOf(..) | Arg::Param(_) => ArgKind::Scalar,
            Arg::Curve(_) => ArgKind::Curve,
        }
    }

    /// The `index`-th free parameter of another constraint.
    pub fn free_of(constraint: ConstraintId, index: usize) -> Self {
        Arg::FreeOf(constraint.0, index)
    }
}

/// Where each argument sits among the blocks a custom residual reads, fixed when the component
/// is built.
#[derive(Debug, Clone, PartialEq)]
pub struct Layout {
    pub(super) slots: Vec<ArgSlot>,
    pub(super) sizes: Vec<usize>,
}

#[derive(Debug, Clone, PartialEq)]
pub(super) enum ArgSlot {
    Point(usize),
    Scalar(usize),
    Curve { first: usize, basis: Box<CurveBasis> },
}

/// The arguments of a custom constraint at the scalar type `T`, in the order the constraint
/// lists them. Each accessor expects the kind its residual declared for that argument
/// ([`super::CustomResidual::arg_kinds`], checked when the constraint is added); asked for another
/// kind or a missing index, it reads NaN.
#[derive(Debug)]
pub struct Args<'a, T> {
    pub(super) x: &'a [&'a [T]],
    pub(super) layout: &'a Layout,
}

impl<'a, T: Scalar> Args<'a, T> {
    /// The number of arguments.
    pub fn len(&self) -> usize {
        self.layout.slots.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.layout.slots.is_empty()
    }

    /// Argument `i` as a point (x, y).
    pub fn point(&self, i: usize) -> [T; 2] {
        match self.layout.slots.get(i) {
            Some(ArgSlot::Point(b)) => [self.x[*b][0], self.x[*b][1]],
            _ => [cst(f64::NAN); 2],
        }
    }

    /// Argument `i` as one number (a radius or a parameter).
    pub fn scalar(&self, i: usize) -> T {
        match self.layout.slots.get(i) {
            Some(ArgSlot::Scalar(b)) => self.x[*b][0],
            _ => cst(f64::NAN),
        }
    }

    /// Argument `i` as a curve.
    pub fn curve(&self, i: usize) -> CurveArg<'a, T> {
        match self.layout.slots.get(i) {
            Some(ArgSlot::Curve { first, basis }) => CurveArg {
                basis: Some(basis),
                points: &self.x[*first..*first + basis.count()],
            },
            _ => CurveArg {
                basis: None,
                points: &[],
            },
        }
    }

    /// Every block read, in order (a point two numbers, a scalar one, a curve one block per
    /// control point): what a plain [`camber_solve::Residual`] would get.
    pub fn blocks(&self) -> &'a [&'a [T]] {
        self.x
    }
}

/// A curve argument at the scalar type `T`: its control points as unknowns, its degree, knots
/// and weights as data.
#[derive(Debug, Clone, Copy)]
pub struct CurveArg<'a, T> {
    basis: Option<&'a CurveBasis>,
    points: &'a [&'a [T]],
}

impl<T: Scalar> CurveArg<'_, T> {
    /// The parametric domain [a, b] (NaN for a missing curve).
    pub fn domain(&self) -> (f64, f64) {
        self.basis.map_or((f64::NAN, f64::NAN), CurveBasis::domain)
    }

    /// The number of control points.
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// Whether it has none (a missing curve).
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// Control point `j`.
    pub fn control_point(&self, j: usize) -> [T; 2] {
        self.points
            .get(j)
            .map_or([cst(f64::NAN); 2], |p| [p[0], p[1]])
    }

    /// C(u) (u clamped to the domain).
    pub fn point(&self, u: T) -> [T; 2] {
        self.derivatives(u)[0]
    }

    /// C(u), C′(u) and C″(u) (u clamped to the domain).
    pub fn derivatives(&self, u: T) -> [[T; 2]; 3] {
        match self.basis {
            Some(b) => b.eval2(self.points, u),
            None => [[cst(f64::NAN); 2]; 3],
        }
    }
}
