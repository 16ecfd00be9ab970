//! The tape under construction: single-assignment nodes of scalars (a vector is two), written
//! by the parser as it reads, with types checked and constants folded on the way.
//!
//! Every node is a scalar; a vector value is a pair of nodes. An operation whose operands are
//! all constants is computed at once (with the same arithmetic as the tape) and must give a
//! finite number; a division by a constant zero is refused where the divisor starts.
//!
//! Two rewrites keep the tape as short as the same residual written by hand:
//! - **affine folding**: a sum, difference, negation, or product or quotient by a constant of
//!   affine combinations (Σ c·x + k) is one combination again, as long as it stays small
//!   ([`MAX_FOLDED_TERMS`] inputs), so `P - Q` is two combinations, not four reads and two
//!   subtractions;
//! - **common subexpressions**: a node equal to one already written (same operation on the same
//!   operands, or the same combination) is that node, so `dot(P - Q, P - Q)` computes `P - Q`
//!   once.

use crate::errors::{Error, Result, TypeWord};
use crate::ops::{Bin, Fun};
use crate::types::{Input, Term, Type, Value};
use std::collections::HashMap;

use crate::MAX_TAPE;

/// The most inputs an affine combination gets by folding (longer sums stay operations, so a
/// long sum does not copy its terms once per addition).
pub(crate) const MAX_FOLDED_TERMS: usize = 8;

/// A node index.
pub(crate) type Reg = u32;

/// One single-assignment node.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Node {
    Const(f64),
    /// Σ c·x + k over `terms[start..end]` of the builder's table.
    Lin {
        start: u32,
        end: u32,
        constant: f64,
    },
    Bin(Bin, Reg, Reg),
    Fun(Fun, Reg),
    Powi(Reg, i32),
    /// The owner's function `func` on `args[start..end]`, writing `outputs` numbers; this node
    /// is output 0.
    Call {
        func: u32,
        start: u32,
        end: u32,
        outputs: u32,
    },
    /// Output `k` ≥ 1 of the call node.
    Output(Reg, u32),
}

/// A typed value under construction: its nodes and where its text starts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Val {
    pub(crate) ty: Type,
    pub(crate) regs: [Reg; 2],
    /// Byte offset of the value's text.
    pub(crate) at: usize,
}

/// The nodes written so far.
#[derive(Debug, Default)]
pub(crate) struct Builder {
    pub(crate) nodes: Vec<Node>,
    /// The constant value of each node, when it is one.
    pub(crate) consts: Vec<Option<f64>>,
    pub(crate) terms: Vec<(Input, f64)>,
    pub(crate) args: Vec<Reg>,
    /// Calls already written (func, args) → node, so x and y of one curve point share it.
    calls: Vec<(u32, Vec<Reg>, Reg)>,
    /// Column of a byte offset.
    pub(crate) columns: Columns,
    /// Nodes already written, for common subexpressions.
    memo: HashMap<Key, Reg>,
}

/// What makes two nodes the same computation (constants by their bits).
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
enum Key {
    Lin(Vec<(Input, u64)>, u64),
    Bin(Bin, Reg, Reg),
    Fun(Fun, Reg),
    Powi(Reg, i32),
}

/// An affine combination being folded: its terms and constant.
type Affine = (Vec<(Input, f64)>, f64);

/// Byte offsets to 1-based character columns of one text.
#[derive(Debug, Default, Clone)]
pub(crate) struct Columns {
    text: String,
}

impl Columns {
    pub(crate) fn new(text: &str) -> Self {
        Self {
            text: text.to_owned(),
        }
    }

    /// The 1-based character column of byte offset `at`.
    pub(crate) fn of(&self, at: usize) -> usize {
        let at = at.min(self.text.len());
        // Offsets come from the parser, always at character boundaries.
        self.text.get(..at).map_or(at, |s| s.chars().count()) + 1
    }
}

impl Builder {
    /// The column of byte offset `at`.
    pub(crate) fn col(&self, at: usize) -> usize {
        self.columns.of(at)
    }

    /// Writes `node` unless an equal one exists (see the module documentation).
    fn push_shared(&mut self, key: Key, node: Node) -> Result<Reg> {
        if let Some(&r) = self.memo.get(&key) {
            return Ok(r);
        }
        let r = self.push(node, None)?;
        self.memo.insert(key, r);
        Ok(r)
    }

    fn push(&mut self, node: Node, value: Option<f64>) -> Result<Reg> {
        if self.nodes.len() + self.terms.len() >= MAX_TAPE {
            return Err(Error::TooLarge { max: MAX_TAPE });
        }
        self.nodes.push(node);
        self.consts.push(value);
        Ok(Reg::try_from(self.nodes.len() - 1).unwrap_or(Reg::MAX))
    }

    /// A constant node; `at` is where the text that gave it starts.
    pub(crate) fn constant(&mut self, value: f64, at: usize) -> Result<Reg> {
        if !value.is_finite() {
            return Err(Error::NonFinite {
                column: self.col(at),
                value,
            });
        }
        self.push(Node::Const(value), Some(value))
    }

    /// The input a node is exactly (1·x + 0), if it is one.
    pub(crate) fn identity(&self, r: Reg) -> Option<Input> {
        match self.nodes.get(r as usize)? {
            Node::Lin {
                start,
                end,
                constant,
            } if *end == *start + 1 && constant.abs() <= 0.0 => {
                let (input, c) = self.terms.get(*start as usize)?;
                ((c - 1.0).abs() <= 0.0).then_some(*input)
            }
            _ => None,
        }
    }

    pub(crate) fn const_of(&self, r: Reg) -> Option<f64> {
        self.consts.get(r as usize).copied().flatten()
    }

    /// The node of Σ c·x + k (zero coefficients dropped; a constant when none is left).
    fn lin(&mut self, mut terms: Vec<(Input, f64)>, constant: f64, at: usize) -> Result<Reg> {
        terms.retain(|(_, c)| *c != 0.0);
        if terms.is_empty() {
            return self.constant(constant, at);
        }
        if !constant.is_finite() || terms.iter().any(|(_, c)| !c.is_finite()) {
            return Err(Error::NonFinite {
                column: self.col(at),
                value: f64::NAN,
            });
        }
        let key = (terms.len() <= MAX_FOLDED_TERMS).then(|| {
            Key::Lin(
                terms.iter().map(|(i, c)| (*i, c.to_bits())).collect(),
                constant.to_bits(),
            )
        });
        if let Some(&r) = key.as_ref().and_then(|k| self.memo.get(k)) {
            return Ok(r);
        }
        if self.nodes.len() + self.terms.len() + terms.len() >= MAX_TAPE {
            return Err(Error::TooLarge { max: MAX_TAPE });
        }
        let start = u32::try_from(self.terms.len()).unwrap_or(u32::MAX);
        self.terms.extend(terms);
        let end = u32::try_from(self.terms.len()).unwrap_or(u32::MAX);
        let r = self.push(
            Node::Lin {
                start,
                end,
                constant,
            },
            None,
        )?;
        if let Some(k) = key {
            self.memo.insert(k, r);
        }
        Ok(r)
    }

    /// The small affine combination node `r` is (a constant is one with no terms).
    fn affine(&self, r: Reg) -> Option<Affine> {
        match self.nodes.get(r as usize)? {
            Node::Const(c) => Some((Vec::new(), *c)),
            Node::Lin {
                start,
                end,
                constant,
            } if (*end - *start) as usize <= MAX_FOLDED_TERMS => Some((
                self.terms.get(*start as usize..*end as usize)?.to_vec(),
                *constant,
            )),
            _ => None,
        }
    }

    /// a·α + b·β as one combination, if it stays small (terms of one input added up).
    fn combine(a: &Affine, alpha: f64, b: &Affine, beta: f64) -> Option<Affine> {
        let mut terms: Vec<(Input, f64)> = a.0.iter().map(|(i, c)| (*i, c * alpha)).collect();
        for (i, c) in &b.0 {
            match terms.iter_mut().find(|(j, _)| j == i) {
                Some(t) => t.1 += c * beta,
                None => terms.push((*i, c * beta)),
            }
        }
        let constant = a.1 * alpha + b.1 * beta;
        let finite = constant.is_finite() && terms.iter().all(|(_, c)| c.is_finite());
        (finite && terms.len() <= MAX_FOLDED_TERMS).then_some((terms, constant))
    }

    /// The folded form of `op` on two nodes when both are small affine combinations and the
    /// result is one too (a product or quotient needs a constant factor or divisor).
    fn fold_affine(&self, op: Bin, a: Reg, b: Reg) -> Option<Affine> {
        let (x, y) = (self.affine(a)?, self.affine(b)?);
        let none = (Vec::new(), 0.0);
        match op {
            Bin::Add => Self::combine(&x, 1.0, &y, 1.0),
            Bin::Sub => Self::combine(&x, 1.0, &y, -1.0),
            Bin::Mul if y.0.is_empty() => Self::combine(&x, y.1, &none, 0.0),
            Bin::Mul if x.0.is_empty() => Self::combine(&y, x.1, &none, 0.0),
            Bin::Div if y.0.is_empty() && y.1 != 0.0 => Self::combine(&x, 1.0 / y.1, &none, 0.0),
            _ => None,
        }
    }

    /// The node of one term of an owner's value.
    pub(crate) fn term(&mut self, t: &Term, args: &[Reg], at: usize) -> Result<Reg> {
        match t {
            Term::Const(c) => self.constant(*c, at),
            Term::Linear { terms, constant } => {
                if !constant.is_finite() || terms.iter().any(|(_, c)| !c.is_finite()) {
                    return Err(Error::NonFinite {
                        column: self.col(at),
                        value: f64::NAN,
                    });
                }
                self.lin(terms.clone(), *constant, at)
            }
            Term::Call {
                func,
                output,
                outputs,
            } => {
                let node = self.call(*func, args.to_vec(), *outputs)?;
                if *output == 0 {
                    Ok(node)
                } else {
                    self.push(Node::Output(node, *output), None)
                }
            }
        }
    }

    /// The call node of `func` on `args` (written once per distinct call).
    fn call(&mut self, func: u32, args: Vec<Reg>, outputs: u32) -> Result<Reg> {
        if let Some((_, _, r)) = self.calls.iter().find(|(f, a, _)| *f == func && *a == args) {
            return Ok(*r);
        }
        let start = u32::try_from(self.args.len()).unwrap_or(u32::MAX);
        self.args.extend(&args);
        let end = u32::try_from(self.args.len()).unwrap_or(u32::MAX);
        let r = self.push(
            Node::Call {
                func,
                start,
                end,
                outputs: outputs.max(1),
            },
            None,
        )?;
        self.calls.push((func, args, r));
        Ok(r)
    }

    /// A value of the owner (a name, member or call result); `args` are the nodes of the
    /// varying arguments of a call.
    pub(crate) fn value(&mut self, v: &Value, args: &[Reg], at: usize) -> Result<Val> {
        Ok(match v {
            Value::Scalar(t) => {
                let r = self.term(t, args, at)?;
                Val {
                    ty: Type::Scalar,
                    regs: [r, r],
                    at,
                }
            }
            Value::Vector([x, y]) => Val {
                ty: Type::Vector,
                regs: [self.term(x, args, at)?, self.term(y, args, at)?],
                at,
            },
        })
    }

    /// A scalar value from a node.
    pub(crate) fn scalar(r: Reg, at: usize) -> Val {
        Val {
            ty: Type::Scalar,
            regs: [r, r],
            at,
        }
    }

    /// A binary operation on two scalar nodes, folded when both are constants.
    pub(crate) fn bin(&mut self, op: Bin, a: Reg, b: Reg, at: usize, b_at: usize) -> Result<Reg> {
        if op == Bin::Div && self.const_of(b) == Some(0.0) {
            return Err(Error::DivisionByZero {
                column: self.col(b_at),
            });
        }
        match (self.const_of(a), self.const_of(b)) {
            (Some(x), Some(y)) => self.constant(op.apply(x, y), at),
            _ => match self.fold_affine(op, a, b) {
                Some((terms, constant)) => self.lin(terms, constant, at),
                None => self.push_shared(Key::Bin(op, a, b), Node::Bin(op, a, b)),
            },
        }
    }

    /// A function of one scalar node, folded on a constant.
    pub(crate) fn fun(&mut self, f: Fun, a: Reg, at: usize) -> Result<Reg> {
        match (self.const_of(a), f) {
            (Some(x), _) => self.constant(f.apply(x), at),
            (None, Fun::Neg) => match self.affine(a) {
                Some((terms, constant)) => {
                    let negated = terms.into_iter().map(|(i, c)| (i, -c)).collect();
                    self.lin(negated, -constant, at)
                }
                None => self.push_shared(Key::Fun(f, a), Node::Fun(f, a)),
            },
            (None, _) => self.push_shared(Key::Fun(f, a), Node::Fun(f, a)),
        }
    }

    /// aⁿ for a constant integer n, folded on a constant a.
    pub(crate) fn powi(&mut self, a: Reg, n: i32, at: usize) -> Result<Reg> {
        match self.const_of(a) {
            Some(x) => self.constant(x.powi(n), at),
            None if n == 1 => Ok(a),
            None => self.push_shared(Key::Powi(a, n), Node::Powi(a, n)),
        }
    }

    /// Fails unless `v` has type `ty`, naming `what` and the operand's column.
    pub(crate) fn expect(&self, v: &Val, ty: Type, what: &str) -> Result<()> {
        if v.ty == ty {
            Ok(())
        } else {
            Err(Error::Type {
                column: self.col(v.at),
                what: what.to_owned(),
                expected: TypeWord(ty),
                found: TypeWord(v.ty),
            })
        }
    }
}
