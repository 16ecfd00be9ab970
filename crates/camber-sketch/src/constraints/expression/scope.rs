//! What the names of an expression constraint stand for in the sketch: its arguments (points,
//! curves, circles, lines, free parameters) and the sketch's named parameters, as
//! combinations of the blocks the residual reads, and the sketch functions the tape calls.
//!
//! Blocks are given out as names are read, each sketch point once: a point, control point or
//! line end is one block (x, y), a circle's radius a block of one, a free parameter a block of
//! one. A curve point at a constant parameter is a constant combination of control points (a
//! linear term, so the row stays affine); at a varying parameter it is a call of the curve's
//! basis over all its control points.

use std::collections::BTreeMap;

use camber_expr::{CallArg, Input, Term, Value};

use super::residual::{Function, Functions};
use super::ExprArg;
use crate::constraints::piece::{ETerms, Slot};
use crate::constraints::Compiler;
use crate::ground::errors::Error;
use crate::ground::ids::{EntityId, PointRef};

/// The names of one expression constraint during its compilation.
pub(crate) struct SketchScope<'c, 'a> {
    cx: &'c Compiler<'a>,
    args: &'c BTreeMap<String, ExprArg>,
    parameters: &'c dyn Fn(&str) -> Option<f64>,
    /// The blocks read, in order.
    pub(crate) slots: Vec<Slot>,
    pub(crate) sizes: Vec<usize>,
    pub(crate) functions: Functions,
    /// The block of each free parameter argument, by name.
    free: BTreeMap<String, usize>,
    /// Calls already made: (curve, order or `usize::MAX` for the length) → function number.
    calls: BTreeMap<(EntityId, usize), u32>,
    /// Argument names read at least once.
    pub(crate) used: std::collections::BTreeSet<String>,
    /// The first error of the sketch's own (an unknown entity, a wrong kind), reported as is.
    pub(crate) failure: Option<Error>,
}

impl<'c, 'a> SketchScope<'c, 'a> {
    /// The scope of `args` over `cx`'s entities; free parameters get the first blocks, in
    /// name order (the k-th free parameter of the constraint is the k-th by name).
    pub(crate) fn new(
        cx: &'c Compiler<'a>,
        args: &'c BTreeMap<String, ExprArg>,
        parameters: &'c dyn Fn(&str) -> Option<f64>,
    ) -> Self {
        let mut s = Self {
            cx,
            args,
            parameters,
            slots: Vec::new(),
            sizes: Vec::new(),
            functions: Functions::default(),
            free: BTreeMap::new(),
            calls: BTreeMap::new(),
            used: std::collections::BTreeSet::new(),
            failure: None,
        };
        for (name, a) in args {
            if let ExprArg::Free(start) = a {
                let b = s.slots.len();
                s.slots.push(Slot::Free {
                    start: *start,
                    lo: f64::NEG_INFINITY,
                    hi: f64::INFINITY,
                });
                s.sizes.push(1);
                s.free.insert(name.clone(), b);
            }
        }
        s
    }

    /// The block of a slot, given out on first use.
    fn block(&mut self, slot: Slot, size: usize) -> usize {
        if let Some(b) = self.slots.iter().position(|s| *s == slot) {
            return b;
        }
        self.slots.push(slot);
        self.sizes.push(size);
        self.slots.len() - 1
    }

    /// A sketch error, kept to be reported as it is; the expression compiler gets its text.
    fn fail(&mut self, e: Error) -> String {
        let text = e.to_string();
        self.failure.get_or_insert(e);
        text
    }

    /// Σ c·P over entity points as a vector of linear terms.
    fn combination(&mut self, terms: &ETerms) -> Value {
        let mut x = Vec::with_capacity(terms.len());
        let mut y = Vec::with_capacity(terms.len());
        for (e, j, c) in terms {
            let b = self.block(Slot::Point(*e, *j), 2);
            x.push((Input::new(b, 0), *c));
            y.push((Input::new(b, 1), *c));
        }
        Value::Vector([
            Term::Linear {
                terms: x,
                constant: 0.0,
            },
            Term::Linear {
                terms: y,
                constant: 0.0,
            },
        ])
    }

    fn point(&mut self, r: PointRef) -> Result<Value, String> {
        let mut terms = ETerms::new();
        match self.cx.point_terms(r, 1.0, &mut terms) {
            Ok(()) => Ok(self.combination(&terms)),
            Err(e) => Err(self.fail(e)),
        }
    }

    /// The curve (line, Bézier, B-spline, NURBS, Hermite, composite) of argument `name`.
    fn curve_of(&mut self, name: &str) -> Option<EntityId> {
        match self.args.get(name)? {
            ExprArg::Curve(e) | ExprArg::Line(e) => Some(*e),
            _ => None,
        }
    }

    /// C⁽ᵏ⁾(u) at a varying u: a call of the curve's basis over all its control points.
    fn curve_call(&mut self, curve: EntityId, order: usize, u: Option<Input>) -> Result<Value, String> {
        let key = (curve, order);
        let func = match self.calls.get(&key) {
            Some(f) => *f,
            None => {
                let (basis, points) = self.cx.curve_basis(curve).map_err(|e| self.fail(e))?;
                let blocks = points
                    .into_iter()
                    .map(|s| u32::try_from(self.block(s, 2)).unwrap_or(u32::MAX))
                    .collect();
                let f = u32::try_from(self.functions.0.len()).unwrap_or(u32::MAX);
                self.functions.0.push(Function::Curve {
                    basis: Box::new(basis),
                    blocks,
                    order,
                });
                self.calls.insert(key, f);
                f
            }
        };
        // A free parameter read directly as u is bounded to the curve's domain.
        if let Some(input) = u {
            let (lo, hi) = self.cx.domain(curve).map_err(|e| self.fail(e))?;
            if let Some(Slot::Free {
                lo: l, hi: h, start, ..
            }) = self.slots.get_mut(input.block as usize)
            {
                if *start < lo || *start > hi {
                    return Err(format!(
                        "the free parameter starts at {start}, outside the domain [{lo}, {hi}] of {curve}"
                    ));
                }
                *l = l.max(lo);
                *h = h.min(hi);
            }
        }
        Ok(Value::Vector([
            Term::Call {
                func,
                output: 0,
                outputs: 2,
            },
            Term::Call {
                func,
                output: 1,
                outputs: 2,
            },
        ]))
    }

    /// The arc length of a curve, by the fixed rule of the `arc_length` kind.
    fn length(&mut self, curve: EntityId) -> Result<Value, String> {
        let key = (curve, usize::MAX);
        if let Some(f) = self.calls.get(&key) {
            return Ok(Value::Scalar(Term::Call {
                func: *f,
                output: 0,
                outputs: 1,
            }));
        }
        let (basis, points) = self.cx.curve_basis(curve).map_err(|e| self.fail(e))?;
        let e = self.cx.entity_values(curve).map_err(|e| self.fail(e))?;
        let now: Vec<[f64; 2]> = e.points().iter().map(|p| [p.x, p.y]).collect();
        let refs: Vec<&[f64]> = now.iter().map(|p| &p[..]).collect();
        let rule = crate::constraints::arc_length::LengthOf::new(
            basis,
            &crate::constraints::arc_length::breakpoints(e),
            &refs,
            0.0,
        );
        let blocks = points
            .into_iter()
            .map(|s| u32::try_from(self.block(s, 2)).unwrap_or(u32::MAX))
            .collect();
        let f = u32::try_from(self.functions.0.len()).unwrap_or(u32::MAX);
        self.functions.0.push(Function::Length { rule, blocks });
        self.calls.insert(key, f);
        Ok(Value::Scalar(Term::Call {
            func: f,
            output: 0,
            outputs: 1,
        }))
    }
}

impl camber_expr::Scope for SketchScope<'_, '_> {
    fn value(&mut self, name: &str) -> Result<Option<Value>, String> {
        let Some(arg) = self.args.get(name).copied() else {
            return Ok((self.parameters)(name).map(|v| Value::Scalar(Term::Const(v))));
        };
        self.used.insert(name.to_owned());
        match arg {
            ExprArg::Point(e) => self.point(PointRef::Point(e)).map(Some),
            ExprArg::Control(e, i) => self.point(PointRef::Control(e, i)).map(Some),
            ExprArg::Start(e) => self.point(PointRef::Start(e)).map(Some),
            ExprArg::End(e) => self.point(PointRef::End(e)).map(Some),
            ExprArg::Free(_) => Ok(self
                .free
                .get(name)
                .map(|b| Value::Scalar(Term::input(Input::new(*b, 0))))),
            ExprArg::Curve(_) => Err(format!(
                "`{name}` is a curve: write {name}(u), {name}'(u), {name}''(u), {name}.start, {name}.end or {name}.length"
            )),
            ExprArg::Line(_) => Err(format!(
                "`{name}` is a line: write {name}.start, {name}.end, {name}.dir or {name}(u)"
            )),
            ExprArg::Circle(_) => Err(format!(
                "`{name}` is a circle: write {name}.center or {name}.radius"
            )),
        }
    }

    fn member(&mut self, name: &str, member: &str) -> Result<Option<Value>, String> {
        let Some(arg) = self.args.get(name).copied() else {
            return Ok(None);
        };
        self.used.insert(name.to_owned());
        match (arg, member) {
            (ExprArg::Curve(e) | ExprArg::Line(e), "start") => self.point(PointRef::Start(e)).map(Some),
            (ExprArg::Curve(e) | ExprArg::Line(e), "end") => self.point(PointRef::End(e)).map(Some),
            (ExprArg::Curve(e) | ExprArg::Line(e), "length") => {
                self.cx.curve(e).map_err(|x| self.fail(x))?;
                self.length(e).map(Some)
            }
            (ExprArg::Line(e), "dir") => {
                self.cx.line(e).map_err(|x| self.fail(x))?;
                let mut terms = ETerms::new();
                terms.push((e, 1, 1.0));
                terms.push((e, 0, -1.0));
                Ok(Some(self.combination(&terms)))
            }
            (ExprArg::Circle(e), "center") => {
                self.cx.circle(e).map_err(|x| self.fail(x))?;
                self.point(PointRef::Control(e, 0)).map(Some)
            }
            (ExprArg::Circle(e), "radius") => {
                self.cx.circle(e).map_err(|x| self.fail(x))?;
                let b = self.block(Slot::Radius(e), 1);
                Ok(Some(Value::Scalar(Term::input(Input::new(b, 0)))))
            }
            (ExprArg::Curve(_), _) => Err(format!(
                "a curve has the members `start`, `end` and `length`, not `{member}`"
            )),
            (ExprArg::Line(_), _) => Err(format!(
                "a line has the members `start`, `end`, `dir` and `length`, not `{member}`"
            )),
            (ExprArg::Circle(_), _) => Err(format!(
                "a circle has the members `center` and `radius`, not `{member}`"
            )),
            _ => Ok(None),
        }
    }

    fn call(
        &mut self,
        name: &str,
        primes: usize,
        args: &[CallArg],
    ) -> Result<Option<Value>, String> {
        let Some(curve) = self.curve_of(name) else {
            return Ok(None);
        };
        self.used.insert(name.to_owned());
        if primes > 2 {
            return Err(format!(
                "derivatives up to the second are available ({name}, {name}', {name}''), not {primes}"
            ));
        }
        self.cx.curve(curve).map_err(|e| self.fail(e))?;
        match args {
            [CallArg::Const(u)] => {
                let terms = self
                    .cx
                    .curve_derivative_terms(curve, *u, primes)
                    .map_err(|e| self.fail(e))?;
                Ok(Some(self.combination(&terms)))
            }
            [CallArg::Varying(input)] => self.curve_call(curve, primes, *input).map(Some),
            [CallArg::Vector] => Err(format!("`{name}` takes a scalar parameter, not a vector")),
            _ => Err(format!(
                "`{name}` takes one argument (the curve parameter), found {}",
                args.len()
            )),
        }
    }
}
