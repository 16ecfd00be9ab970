//! `custom`: a user-written residual over any unknowns of the sketch, through the same path as
//! every built-in kind.
//!
//! A custom constraint lists its arguments ([`Arg`]): points, circle radii, whole curves (their
//! control points, evaluated with the curve's degree, knots and weights as they are when the
//! component is built, so a refined curve is evaluated right), free parameters of other
//! constraints (a contact parameter), and free parameters of its own (unknowns it adds, stored
//! back after a solve). Its residual is written once, generically over the scalar type, either
//!
//! - as a [`CustomResidual`] over typed arguments ([`Args`]: `point(i)`, `scalar(i)`,
//!   `curve(i).point(u)`, …), made with [`Custom::with_args`]; or
//! - as a plain [`camber_solve::Residual`] over point blocks, made with [`Custom::new`].
//!
//! **Shapes are declared and checked once**: a [`CustomResidual`] declares the kind of each
//! argument it reads ([`CustomResidual::arg_kinds`]), a plain residual the length of each block
//! ([`camber_solve::Residual::block_sizes`]); adding a constraint whose arguments do not match
//! is refused with [`crate::Error::CustomArgs`] (or [`crate::Error::UndeclaredBlocks`]), so an
//! `eval` may index its arguments freely.
//!
//! File form: `{"kind": "custom", "name": "gap", "points": [{"point": 0}, {"point": 1}],
//! "params": {"gap": 2}}` (points only), or with `"args": [{"curve": 0}, {"param": 0.5}, …]`;
//! a [`crate::file::CustomRegistry`] decodes it by name.

use std::any::Any;
use std::sync::Arc;

use camber_solve::scalar::cst;
use camber_solve::{ConstraintId, DynResidual, Residual, Scalar};
use serde::{Deserialize, Serialize};
use serde_json::Value;
use smallvec::SmallVec;

use super::compiler::finite;
use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::component::piece::Slot;
use crate::curve_eval::CurveBasis;
use crate::errors::{Error, Result};
use crate::ids::{EntityId, PointRef};
use crate::lookup::EntityLookup;

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

/// What an argument is, as a residual declares it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ArgKind {
    /// A point (x, y).
    Point,
    /// One number: a radius, another constraint's free parameter, or an own parameter.
    Scalar,
    /// A whole curve.
    Curve,
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
    slots: Vec<ArgSlot>,
    sizes: Vec<usize>,
}

#[derive(Debug, Clone, PartialEq)]
enum ArgSlot {
    Point(usize),
    Scalar(usize),
    Curve { first: usize, basis: Box<CurveBasis> },
}

/// The arguments of a custom constraint at the scalar type `T`, in the order the constraint
/// lists them. Each accessor expects the kind its residual declared for that argument
/// ([`CustomResidual::arg_kinds`], checked when the constraint is added); asked for another
/// kind or a missing index, it reads NaN.
#[derive(Debug)]
pub struct Args<'a, T> {
    x: &'a [&'a [T]],
    layout: &'a Layout,
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

/// A custom constraint's residual over typed arguments, written once generically over the
/// scalar type; its exact Jacobian comes from dual numbers like every built-in's.
///
/// ```
/// use camber_sketch::constraints::custom::{Arg, ArgKind, Args, Custom, CustomResidual};
/// use camber_sketch::{PointRef, Sketch};
/// use camber_geom::BezierCurve2;
/// use camber_solve::Scalar;
/// use nalgebra::Point2;
/// /// The curve passes through the point at its own free parameter s: C(s) − P = 0.
/// #[derive(Debug)]
/// struct Through;
/// impl CustomResidual for Through {
///     fn name(&self) -> &str { "through" }
///     fn dim(&self) -> usize { 2 }
///     fn arg_kinds(&self) -> Vec<ArgKind> { vec![ArgKind::Curve, ArgKind::Point, ArgKind::Scalar] }
///     fn eval<T: Scalar>(&self, a: &Args<'_, T>, out: &mut [T]) {
///         let (c, p) = (a.curve(0).point(a.scalar(2)), a.point(1));
///         out[0] = c[0] - p[0];
///         out[1] = c[1] - p[1];
///     }
/// }
/// let mut s = Sketch::new();
/// let c = s.add_bezier(BezierCurve2::try_new(vec![Point2::new(0.0, 0.0), Point2::new(1.0, 1.0), Point2::new(2.0, 0.0)])?)?;
/// let p = s.add_point(Point2::new(1.0, 1.0))?;
/// let id = s.add_constraint(Custom::with_args(Through, vec![Arg::Curve(c), Arg::Point(PointRef::Point(p)), Arg::Param(0.5)]))?;
/// s.solve()?;
/// let Some(Arg::Param(u)) = s.constraint(id)?.as_custom().map(|k| k.args()[2]) else { panic!() };
/// let (on, q) = (s.curve_point(c, u)?, s.point(PointRef::Point(p))?);
/// assert!((on - q).norm() < 1e-10);
/// # Ok::<(), camber_sketch::Error>(())
/// ```
pub trait CustomResidual: std::fmt::Debug + Send + Sync + 'static {
    /// A short name used in reports.
    fn name(&self) -> &str;
    /// Rows it contributes.
    fn dim(&self) -> usize;
    /// The kind of each argument it reads, in order (checked against the constraint's
    /// arguments when it is added).
    fn arg_kinds(&self) -> Vec<ArgKind>;
    /// Writes the residual into `out` (`dim()` entries).
    fn eval<T: Scalar>(&self, args: &Args<'_, T>, out: &mut [T]);
    /// Whether the residual is affine in the unknowns it reads.
    fn is_affine(&self) -> bool {
        false
    }
}

/// The residual of one build: a user residual with its arguments' places.
#[derive(Debug)]
struct Built<R> {
    inner: Arc<R>,
    layout: Layout,
}

impl<R: CustomResidual> Residual for Built<R> {
    fn name(&self) -> &str {
        self.inner.name()
    }
    fn dim(&self) -> usize {
        self.inner.dim()
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(self.layout.sizes.clone())
    }
    fn is_affine(&self) -> bool {
        self.inner.is_affine()
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        self.inner.eval(
            &Args {
                x,
                layout: &self.layout,
            },
            out,
        );
    }
}

/// A plain [`camber_solve::Residual`] over point (and scalar) blocks as a custom residual.
#[derive(Debug)]
struct Plain<R>(R);

impl<R: Residual> CustomResidual for Plain<R> {
    fn name(&self) -> &str {
        self.0.name()
    }
    fn dim(&self) -> usize {
        self.0.dim()
    }
    fn arg_kinds(&self) -> Vec<ArgKind> {
        // Checked to be Some(…) of 1s and 2s before the constraint is accepted.
        self.0
            .block_sizes()
            .unwrap_or_default()
            .iter()
            .map(|n| if *n == 2 { ArgKind::Point } else { ArgKind::Scalar })
            .collect()
    }
    fn eval<T: Scalar>(&self, args: &Args<'_, T>, out: &mut [T]) {
        self.0.eval(args.blocks(), out);
    }
    fn is_affine(&self) -> bool {
        self.0.is_affine()
    }
}

/// The object-safe face of a user residual: it makes the residual of one build.
trait Erased: std::fmt::Debug + Send + Sync {
    fn name(&self) -> &str;
    /// The declared argument kinds (`None`: a plain residual that declares no block sizes).
    fn arg_kinds(&self) -> Option<Vec<ArgKind>>;
    fn build(&self, layout: Layout) -> Arc<dyn DynResidual>;
    fn as_any(&self) -> &dyn Any;
}

#[derive(Debug)]
struct Typed<R>(Arc<R>);

impl<R: CustomResidual> Erased for Typed<R> {
    fn name(&self) -> &str {
        self.0.name()
    }
    fn arg_kinds(&self) -> Option<Vec<ArgKind>> {
        Some(self.0.arg_kinds())
    }
    fn build(&self, layout: Layout) -> Arc<dyn DynResidual> {
        Arc::new(Built {
            inner: self.0.clone(),
            layout,
        })
    }
    fn as_any(&self) -> &dyn Any {
        &*self.0
    }
}

#[derive(Debug)]
struct PlainErased<R>(Arc<Plain<R>>);

impl<R: Residual> Erased for PlainErased<R> {
    fn name(&self) -> &str {
        self.0 .0.name()
    }
    fn arg_kinds(&self) -> Option<Vec<ArgKind>> {
        let sizes = self.0 .0.block_sizes()?;
        sizes
            .iter()
            .all(|n| *n == 1 || *n == 2)
            .then(|| self.0.arg_kinds())
    }
    fn build(&self, layout: Layout) -> Arc<dyn DynResidual> {
        Arc::new(Built {
            inner: self.0.clone(),
            layout,
        })
    }
    fn as_any(&self) -> &dyn Any {
        &self.0 .0
    }
}

/// The most rows a custom residual may have: 2²⁰. A solve allocates its values, Jacobian and
/// dual-number buffers by the declared row count, so a row count from a typing slip
/// (`dim=10**9`) is refused when the constraint is compiled ([`crate::Error::CustomTooLarge`])
/// instead of exhausting memory.
pub const MAX_CUSTOM_ROWS: usize = 1 << 20;

/// The most entries of a custom residual's Jacobian block (rows × unknowns its arguments read):
/// 2²⁶, half a gigabyte of f64.
pub const MAX_CUSTOM_JACOBIAN: usize = 1 << 26;

/// A user-written constraint (see the module documentation).
///
/// ```
/// use camber_sketch::{Custom, PointRef, Sketch};
/// use camber_solve::{Residual, Scalar};
/// use nalgebra::Point2;
/// /// The two points are one unit apart in x: q.x − p.x − 1 = 0.
/// #[derive(Debug)]
/// struct UnitApart;
/// impl Residual for UnitApart {
///     fn name(&self) -> &str { "unit apart" }
///     fn dim(&self) -> usize { 1 }
///     fn block_sizes(&self) -> Option<Vec<usize>> { Some(vec![2, 2]) }
///     fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) { out[0] = x[1][0] - x[0][0] - T::one(); }
///     fn is_affine(&self) -> bool { true }
/// }
/// let mut s = Sketch::new();
/// let (p, q) = (s.add_point(Point2::new(0.0, 0.0))?, s.add_point(Point2::new(3.0, 0.0))?);
/// s.add_constraint(Custom::new(UnitApart, vec![PointRef::Point(p), PointRef::Point(q)]))?;
/// s.solve()?;
/// assert!((s.point(PointRef::Point(q))?.x - s.point(PointRef::Point(p))?.x - 1.0).abs() < 1e-12);
/// // Given one point where it reads two, it is refused, not evaluated out of bounds.
/// assert!(s.add_constraint(Custom::new(UnitApart, vec![PointRef::Point(p)])).is_err());
/// # Ok::<(), camber_sketch::Error>(())
/// ```
#[derive(Clone)]
pub struct Custom {
    residual: Option<Arc<dyn Erased>>,
    args: Vec<Arg>,
    /// The kind name and parameters a sketch file stores it under (see [`crate::file`]).
    file_form: Option<(String, Value)>,
}

impl Custom {
    /// A custom constraint with a plain residual reading `points` (one block of two each, in
    /// order). The residual must declare its block sizes ([`Residual::block_sizes`]).
    pub fn new<R: Residual>(residual: R, points: Vec<PointRef>) -> Self {
        Self::plain(residual, points.into_iter().map(Arg::Point).collect())
    }

    /// A custom constraint with a plain residual reading `args` in order: a point gives a block
    /// of two, a radius or parameter a block of one (a curve is for [`CustomResidual`]s). The
    /// residual must declare its block sizes ([`Residual::block_sizes`]).
    pub fn plain<R: Residual>(residual: R, args: Vec<Arg>) -> Self {
        Self {
            residual: Some(Arc::new(PlainErased(Arc::new(Plain(residual))))),
            args,
            file_form: None,
        }
    }

    /// A custom constraint with a residual over typed arguments.
    pub fn with_args<R: CustomResidual>(residual: R, args: Vec<Arg>) -> Self {
        Self {
            residual: Some(Arc::new(Typed(Arc::new(residual)))),
            args,
            file_form: None,
        }
    }

    /// The arguments, with the current values of its own parameters.
    pub fn args(&self) -> &[Arg] {
        &self.args
    }

    /// The points read, when every argument is a point.
    pub fn points(&self) -> Vec<PointRef> {
        self.args
            .iter()
            .filter_map(|a| match a {
                Arg::Point(p) => Some(*p),
                _ => None,
            })
            .collect()
    }

    /// The residual's name ("" for a constraint read from a file and not decoded).
    pub fn name(&self) -> &str {
        self.residual.as_ref().map_or("", |r| r.name())
    }

    /// The user's residual, for downcasting (a [`CustomResidual`] or a plain residual).
    pub fn residual_any(&self) -> Option<&dyn Any> {
        self.residual.as_ref().map(|r| r.as_any())
    }

    /// The same constraint, saved in sketch files as kind `name` with `params` (what a
    /// [`crate::file::CustomRegistry`] decoder registered under `name` reads back).
    pub fn with_file_form(mut self, name: impl Into<String>, params: Value) -> Self {
        self.file_form = Some((name.into(), params));
        self
    }

    /// The kind name and parameters the constraint is saved under, if any.
    pub fn file_form(&self) -> Option<(&str, &Value)> {
        self.file_form.as_ref().map(|(n, p)| (n.as_str(), p))
    }

    /// Whether the residual is present (a constraint read from a file holds only its name and
    /// arguments until a registry decodes it).
    pub fn is_decoded(&self) -> bool {
        self.residual.is_some()
    }
}

impl std::fmt::Debug for Custom {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Custom")
            .field("residual", &self.name())
            .field("args", &self.args)
            .finish()
    }
}

/// Two custom constraints are equal when they share the same residual object and arguments.
impl PartialEq for Custom {
    fn eq(&self, other: &Self) -> bool {
        let same = match (&self.residual, &other.residual) {
            (Some(a), Some(b)) => Arc::ptr_eq(a, b),
            (None, None) => self.file_form == other.file_form,
            _ => false,
        };
        same && self.args == other.args
    }
}

/// The file form: `{"name", "points" | "args", "params"}`.
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct CustomForm {
    name: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    points: Option<Vec<PointRef>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    args: Option<Vec<Arg>>,
    #[serde(default, skip_serializing_if = "Value::is_null")]
    params: Value,
}

impl Serialize for Custom {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        let Some((name, params)) = &self.file_form else {
            return Err(serde::ser::Error::custom(format!(
                "the custom constraint \"{}\" has no file form",
                self.name()
            )));
        };
        let all_points = self.args.iter().all(|a| matches!(a, Arg::Point(_)));
        CustomForm {
            name: name.clone(),
            points: all_points.then(|| self.points()),
            args: (!all_points).then(|| self.args.clone()),
            params: params.clone(),
        }
        .serialize(s)
    }
}

impl<'de> Deserialize<'de> for Custom {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        let form = CustomForm::deserialize(d)?;
        let args = match (form.points, form.args) {
            (Some(points), None) => points.into_iter().map(Arg::Point).collect(),
            (None, Some(args)) => args,
            (None, None) => Vec::new(),
            (Some(_), Some(_)) => {
                return Err(serde::de::Error::custom(
                    "a custom constraint lists either \"points\" or \"args\", not both",
                ))
            }
        };
        Ok(Custom {
            residual: None,
            args,
            file_form: Some((form.name, form.params)),
        })
    }
}

impl ConstraintKind for Custom {
    const TAG: &'static str = "custom";
    const LABEL: &'static str = "custom";

    fn entities(&self, out: &mut Entities) {
        for a in &self.args {
            match a {
                Arg::Point(p) => out.add_point(*p),
                Arg::Radius(e) | Arg::Curve(e) => out.add(*e),
                Arg::FreeOf(..) | Arg::Param(_) => {}
            }
        }
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let Some(residual) = &self.residual else {
            return Err(Error::UnresolvedCustom {
                name: self.file_form.as_ref().map_or_else(String::new, |f| f.0.clone()),
            });
        };
        let Some(expected) = residual.arg_kinds() else {
            return Err(Error::UndeclaredBlocks {
                name: residual.name().to_owned(),
            });
        };
        let found: Vec<ArgKind> = self.args.iter().map(Arg::kind).collect();
        if expected != found {
            return Err(Error::CustomArgs {
                name: residual.name().to_owned(),
                expected,
                found,
            });
        }
        let mut slots = Vec::with_capacity(self.args.len());
        let mut layout = Layout {
            slots: Vec::with_capacity(self.args.len()),
            sizes: Vec::with_capacity(self.args.len()),
        };
        for a in &self.args {
            let at = slots.len();
            match *a {
                Arg::Point(r) => {
                    let (e, j) = cx.single_block(r)?;
                    slots.push(Slot::Point(e, j));
                    layout.slots.push(ArgSlot::Point(at));
                    layout.sizes.push(2);
                }
                Arg::Radius(e) => {
                    cx.circle(e)?;
                    slots.push(Slot::Radius(e));
                    layout.slots.push(ArgSlot::Scalar(at));
                    layout.sizes.push(1);
                }
                Arg::Curve(e) => {
                    let (basis, points) = cx.curve_basis(e)?;
                    layout.sizes.extend(std::iter::repeat_n(2, points.len()));
                    slots.extend(points);
                    layout.slots.push(ArgSlot::Curve {
                        first: at,
                        basis: Box::new(basis),
                    });
                }
                Arg::FreeOf(c, k) => {
                    slots.push(Slot::FreeOf(ConstraintId(c), k));
                    layout.slots.push(ArgSlot::Scalar(at));
                    layout.sizes.push(1);
                }
                Arg::Param(v) => {
                    let start = finite("custom parameter", v)?;
                    slots.push(Slot::Free {
                        start,
                        lo: f64::NEG_INFINITY,
                        hi: f64::INFINITY,
                    });
                    layout.slots.push(ArgSlot::Scalar(at));
                    layout.sizes.push(1);
                }
            }
        }
        let unknowns: usize = layout.sizes.iter().sum();
        let built = residual.build(layout);
        let rows = built.dim();
        if rows > MAX_CUSTOM_ROWS || rows.saturating_mul(unknowns) > MAX_CUSTOM_JACOBIAN {
            return Err(Error::CustomTooLarge {
                name: residual.name().to_owned(),
                rows,
                unknowns,
                max_rows: MAX_CUSTOM_ROWS,
                max_entries: MAX_CUSTOM_JACOBIAN,
            });
        }
        cx.residual(built, slots, None);
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        self.points()
            .into_iter()
            .map(|r| glyph::point(at, r).map(Glyph::Ring))
            .collect()
    }

    fn set_free_parameter(&mut self, k: usize, value: f64) {
        if let Some(Arg::Param(v)) = self
            .args
            .iter_mut()
            .filter(|a| matches!(a, Arg::Param(_)))
            .nth(k)
        {
            *v = value;
        }
    }

    fn reads_constraints(&self) -> SmallVec<[ConstraintId; 2]> {
        self.args
            .iter()
            .filter_map(|a| match a {
                Arg::FreeOf(c, _) => Some(ConstraintId(*c)),
                _ => None,
            })
            .collect()
    }
}

impl super::Constraint {
    /// The custom constraint inside, if this is one.
    pub fn as_custom(&self) -> Option<&Custom> {
        match self {
            super::Constraint::Custom(c) => Some(c),
            _ => None,
        }
    }
}
