//! `expression`: rows written as text over the sketch's quantities, compiled once by
//! [`camber_expr`] to a tape whose values, exact Jacobians and Hessians come from the same dual
//! numbers as every built-in kind's.
//!
//! File form:
//!
//! ```json
//! {"kind": "expression", "name": "chord", "rows": ["norm(T - L) = 2 * r"],
//!  "args": {"L": {"start": 0}, "T": {"end": 0}, "r": {"free": 0.5}}}
//! ```
//!
//! Each argument names a sketch quantity ([`ExprArg`]): a point (`{"point": e}`,
//! `{"control": [e, i]}`, `{"start": e}`, `{"end": e}`: a vector), a curve (`{"curve": e}`:
//! `C(u)`, `C'(u)`, `C''(u)`, `C.start`, `C.end`, `C.length`), a line (`{"line": e}`: also
//! `L.dir` = end − start), a circle (`{"circle": e}`: `K.center`, `K.radius`), or a free
//! parameter of the constraint's own (`{"free": start}`: an unknown, written back after a
//! solve). The sketch's named parameters are read by name. A row is a scalar or a vector (two
//! rows); `a = b` is the row a − b. A curve point at a constant parameter is a constant
//! combination of control points, so `cross(C'(0), [1, 0])` is affine and takes the one-step
//! linear path; the tape decides ([`camber_expr::Program::is_affine`]). A free parameter read
//! as a curve's parameter (`C(s)`) is bounded to the curve's domain.
//!
//! ```
//! use std::collections::BTreeMap;
//! use camber_sketch::constraints::expression::{ExprArg, Expression};
//! use camber_sketch::{PointRef, Sketch};
//! use nalgebra::Point2;
//! let mut s = Sketch::new();
//! let (p, q) = (s.add_point(Point2::new(0.0, 0.0))?, s.add_point(Point2::new(3.0, 1.0))?);
//! let e = Expression::new("gap", &["norm(Q - P) = 2"])
//!     .with_arg("P", ExprArg::Point(p))
//!     .with_arg("Q", ExprArg::Point(q));
//! s.add_constraint(e)?;
//! s.solve()?;
//! let d = s.point(PointRef::Point(q))? - s.point(PointRef::Point(p))?;
//! assert!((d.norm() - 2.0).abs() < 1e-10);
//! // A bad row is refused with its column, and nothing is added.
//! let bad = Expression::new("", &["norm(Q) + 1 +"]).with_arg("Q", ExprArg::Point(q));
//! assert_eq!(s.add_constraint(bad).unwrap_err().to_string(),
//!            "column 14: expected an operand (a number, a name, `(` or `[`), found the end of the expression");
//! # Ok::<(), camber_sketch::Error>(())
//! ```

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use super::glyph::{self, Glyph};
use super::{Compiler, ConstraintKind, Entities};
use crate::errors::{Error, Result};
use crate::ids::{EntityId, PointRef};
use crate::lookup::EntityLookup;

pub mod residual;
mod scope;

pub use residual::ExpressionResidual;

/// What a name of an expression stands for.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum ExprArg {
    /// A point entity (a vector).
    Point(EntityId),
    /// Control point `i` of an entity: a line end, a circle's centre (i = 0) (a vector).
    Control(EntityId, usize),
    /// The start C(a) of a curve (a vector).
    Start(EntityId),
    /// The end C(b) of a curve (a vector).
    End(EntityId),
    /// A curve: `C(u)`, `C'(u)`, `C''(u)`, `C.start`, `C.end`, `C.length`.
    Curve(EntityId),
    /// A line entity: `L.start`, `L.end`, `L.dir`, `L(u)`, `L.length`.
    Line(EntityId),
    /// A circle entity: `K.center`, `K.radius`.
    Circle(EntityId),
    /// A free parameter of the constraint's own, starting here: an unknown of the solve,
    /// written back after a successful one.
    Free(f64),
}

impl ExprArg {
    /// The entity it reads, if any.
    pub fn entity(&self) -> Option<EntityId> {
        match self {
            ExprArg::Point(e)
            | ExprArg::Control(e, _)
            | ExprArg::Start(e)
            | ExprArg::End(e)
            | ExprArg::Curve(e)
            | ExprArg::Line(e)
            | ExprArg::Circle(e) => Some(*e),
            ExprArg::Free(_) => None,
        }
    }
}

/// A block an expression residual reads ([`Expression::residual_for`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ExprBlock {
    /// Point `index` of an entity (x, y).
    Point(EntityId, usize),
    /// A circle's radius.
    Radius(EntityId),
    /// A free parameter of the constraint, starting at `start`, bounded to [lo, hi].
    Free {
        /// Its value now.
        start: f64,
        /// Lower bound (−∞ when unbounded).
        lo: f64,
        /// Upper bound (+∞ when unbounded).
        hi: f64,
    },
}

/// Rows written as text over named sketch quantities (see the module documentation).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Expression {
    /// A name for reports and pictures (may be empty).
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub name: String,
    /// The rows: each a scalar or vector expression, `a = b` meaning a − b.
    pub rows: Vec<String>,
    /// What each name stands for.
    #[serde(default)]
    pub args: BTreeMap<String, ExprArg>,
}

impl Expression {
    /// An expression named `name` with `rows` and no arguments yet.
    pub fn new(name: &str, rows: &[&str]) -> Self {
        Self {
            name: name.to_owned(),
            rows: rows.iter().map(|r| (*r).to_owned()).collect(),
            args: BTreeMap::new(),
        }
    }

    /// The same with `name` standing for `arg`.
    pub fn with_arg(mut self, name: &str, arg: ExprArg) -> Self {
        self.args.insert(name.to_owned(), arg);
        self
    }

    /// The current values of its free parameters, by name.
    pub fn free_parameters(&self) -> BTreeMap<&str, f64> {
        self.args
            .iter()
            .filter_map(|(n, a)| match a {
                ExprArg::Free(v) => Some((n.as_str(), *v)),
                _ => None,
            })
            .collect()
    }

    /// Compiles the rows against the entities (and named parameters) of `lookup` into the
    /// residual and the blocks it reads, in order: what a component's problem is given (for
    /// tests and benchmarks that evaluate the residual alone).
    ///
    /// # Errors
    /// As adding the constraint to a sketch.
    pub fn residual_for(
        &self,
        lookup: &dyn EntityLookup,
    ) -> Result<(ExpressionResidual, Vec<ExprBlock>)> {
        use crate::component::piece::Slot;
        let cx = Compiler::new(lookup);
        let parameters = |name: &str| lookup.parameter(name);
        let (residual, slots) = self.residual(&cx, &parameters)?;
        let blocks = slots
            .into_iter()
            .map(|s| match s {
                Slot::Point(e, j) => ExprBlock::Point(e, j),
                Slot::Radius(e) => ExprBlock::Radius(e),
                Slot::Free { start, lo, hi } => ExprBlock::Free { start, lo, hi },
                // An expression reads no other kind of block.
                Slot::FreeOf(..) | Slot::Existing(_) => ExprBlock::Free {
                    start: f64::NAN,
                    lo: f64::NAN,
                    hi: f64::NAN,
                },
            })
            .collect();
        Ok((residual, blocks))
    }

    /// Compiles the rows against the entities of `cx` (and the sketch's named parameters)
    /// into the residual and the slots it reads.
    pub(crate) fn residual(
        &self,
        cx: &Compiler<'_>,
        parameters: &dyn Fn(&str) -> Option<f64>,
    ) -> Result<(ExpressionResidual, Vec<crate::component::piece::Slot>)> {
        for (name, a) in &self.args {
            check_name(name)?;
            if let ExprArg::Free(v) = a {
                super::compiler::finite("free parameter", *v)?;
            }
            if parameters(name).is_some() {
                return Err(Error::Expression(camber_expr::Error::Scope {
                    column: 1,
                    message: format!("the argument `{name}` hides the sketch parameter of that name"),
                }));
            }
        }
        let mut scope = scope::SketchScope::new(cx, &self.args, parameters);
        let rows: Vec<&str> = self.rows.iter().map(String::as_str).collect();
        let compiled = camber_expr::compile(&rows, &mut scope);
        if let Some(e) = scope.failure.take() {
            return Err(e);
        }
        let program = compiled?;
        if let Some(unused) = self.args.keys().find(|n| !scope.used.contains(*n)) {
            return Err(Error::Expression(camber_expr::Error::Scope {
                column: 1,
                message: format!("the argument `{unused}` is not used by any row"),
            }));
        }
        let residual =
            ExpressionResidual::new(self.name.clone(), program, scope.functions, scope.sizes);
        Ok((residual, scope.slots))
    }
}

/// An argument name: a name of the language, not one of its functions or constants.
fn check_name(name: &str) -> Result<()> {
    let mut chars = name.chars();
    let ok = chars
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_');
    if !ok {
        return Err(Error::Expression(camber_expr::Error::Scope {
            column: 1,
            message: format!("`{name}` is not a name (a letter or _, then letters, digits or _)"),
        }));
    }
    if camber_expr::is_reserved(name) {
        return Err(Error::Expression(camber_expr::Error::Scope {
            column: 1,
            message: format!("`{name}` is a built-in function or constant of the language"),
        }));
    }
    Ok(())
}

impl ConstraintKind for Expression {
    const TAG: &'static str = "expression";
    const LABEL: &'static str = "expression";

    fn entities(&self, out: &mut Entities) {
        for a in self.args.values() {
            if let Some(e) = a.entity() {
                out.add(e);
            }
        }
    }

    fn compile(&self, cx: &mut Compiler<'_>) -> Result<()> {
        let parameters = |name: &str| cx.parameter(name);
        let (residual, slots) = self.residual(cx, &parameters)?;
        cx.residual(residual, slots, None);
        Ok(())
    }

    fn glyphs(&self, at: &dyn EntityLookup) -> Result<Vec<Glyph>> {
        // A mark at the first point argument (or the first curve's middle).
        for a in self.args.values() {
            let p = match a {
                ExprArg::Point(e) => glyph::point(at, PointRef::Point(*e))?,
                ExprArg::Control(e, i) => glyph::point(at, PointRef::Control(*e, *i))?,
                ExprArg::Start(e) => glyph::point(at, PointRef::Start(*e))?,
                ExprArg::End(e) => glyph::point(at, PointRef::End(*e))?,
                _ => continue,
            };
            return Ok(vec![Glyph::Mark(p, "ƒ")]);
        }
        for a in self.args.values() {
            if let ExprArg::Curve(e) | ExprArg::Line(e) = a {
                let (lo, hi) = (
                    glyph::domain_end(at, *e, false)?,
                    glyph::domain_end(at, *e, true)?,
                );
                return Ok(vec![Glyph::Mark(
                    glyph::curve_point(at, *e, 0.5 * (lo + hi))?,
                    "ƒ",
                )]);
            }
            if let ExprArg::Circle(e) = a {
                return Ok(vec![Glyph::Mark(glyph::point(at, PointRef::Control(*e, 0))?, "ƒ")]);
            }
        }
        Ok(Vec::new())
    }

    fn set_free_parameter(&mut self, k: usize, value: f64) {
        if let Some(ExprArg::Free(v)) = self
            .args
            .values_mut()
            .filter(|a| matches!(a, ExprArg::Free(_)))
            .nth(k)
        {
            *v = value;
        }
    }
}
