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

mod args;
mod residual;

use std::any::Any;
use std::sync::Arc;

use camber_solve::{ConstraintId, Residual};
use serde::{Deserialize, Serialize};
use serde_json::Value;
use smallvec::SmallVec;

pub use args::{Arg, ArgKind, Args, CurveArg, Layout};
pub use residual::CustomResidual;
use args::ArgSlot;
use residual::{Boxed, Erased, Plain, PlainErased, Typed};

use super::compiler::finite;
use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::constraints::piece::Slot;
use crate::ground::errors::{Error, Result};
use crate::ground::ids::PointRef;
use crate::ground::lookup::EntityLookup;

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

    /// A custom constraint with a boxed residual ([`camber_solve::DynResidual`], for residuals
    /// that give their own derivatives rather than through dual numbers: a residual written in
    /// another language, say) reading `args` in order, whose kinds it declares in `kinds`
    /// (checked against `args` when the constraint is added). It reads the blocks a plain
    /// residual would (a point two numbers, a radius or parameter one), and a curve argument as
    /// one block of two per control point; its Jacobian columns follow those blocks in order.
    ///
    /// ```
    /// use std::sync::Arc;
    /// use camber_sketch::{Arg, ArgKind, Custom, PointRef, Sketch};
    /// use camber_solve::{Residual, Scalar};
    /// use nalgebra::Point2;
    /// /// q.x − p.x − 1 = 0, boxed as camber-solve's object-safe face.
    /// #[derive(Debug)]
    /// struct UnitApart;
    /// impl Residual for UnitApart {
    ///     fn name(&self) -> &str { "unit apart" }
    ///     fn dim(&self) -> usize { 1 }
    ///     fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) { out[0] = x[1][0] - x[0][0] - T::one(); }
    /// }
    /// let mut s = Sketch::new();
    /// let (p, q) = (s.add_point(Point2::new(0.0, 0.0))?, s.add_point(Point2::new(3.0, 0.0))?);
    /// let args = vec![Arg::Point(PointRef::Point(p)), Arg::Point(PointRef::Point(q))];
    /// s.add_constraint(Custom::boxed(Arc::new(UnitApart), vec![ArgKind::Point; 2], args))?;
    /// s.solve()?;
    /// assert!((s.point(PointRef::Point(q))?.x - s.point(PointRef::Point(p))?.x - 1.0).abs() < 1e-12);
    /// # Ok::<(), camber_sketch::Error>(())
    /// ```
    pub fn boxed(
        residual: Arc<dyn camber_solve::DynResidual>,
        kinds: Vec<ArgKind>,
        args: Vec<Arg>,
    ) -> Self {
        Self {
            residual: Some(Arc::new(Boxed {
                inner: residual,
                kinds,
            })),
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
