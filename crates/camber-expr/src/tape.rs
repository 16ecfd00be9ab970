//! The compiled form: a flat list of scalar instructions over a few registers, evaluated
//! generically over [`Scalar`], with its affinity decided once from the nodes.
//!
//! Finishing a build keeps only the nodes the rows need, fuses an operation with a constant
//! operand into one instruction (x·c, x + c, c − x, c/x), and gives each value a register that
//! is reused once its last reader has run, so a long expression evaluates in a handful of
//! registers kept on the stack: evaluation does not allocate for up to 32 registers.
//!
//! **Affinity.** Each node is constant, affine in the inputs, or nonlinear: inputs and
//! combinations Σ c·x + k are affine; a sum of affine nodes is affine; a product is affine when
//! one factor is constant, a quotient when the divisor is; any function of a non-constant node,
//! and every call of the owner, is nonlinear. The program is affine when every row is.

use camber_scalar::{cst, Scalar};
use smallvec::SmallVec;

use crate::builder::{Builder, Node, Reg, Val};
use crate::ops::{Bin, Fun};
use crate::scope::Externals;
use crate::types::{Input, Type};

/// One instruction; registers are indices into the evaluation's register file.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Ins {
    Const {
        dst: u32,
        value: f64,
    },
    Input {
        dst: u32,
        input: Input,
    },
    Lin {
        dst: u32,
        start: u32,
        end: u32,
        constant: f64,
    },
    Bin {
        dst: u32,
        op: Bin,
        a: u32,
        b: u32,
    },
    /// a op c.
    BinC {
        dst: u32,
        op: Bin,
        a: u32,
        c: f64,
    },
    /// c op b.
    CBin {
        dst: u32,
        op: Bin,
        c: f64,
        b: u32,
    },
    Fun {
        dst: u32,
        f: Fun,
        a: u32,
    },
    Powi {
        dst: u32,
        a: u32,
        n: i32,
    },
    /// Writes `outputs` registers from `dst` on.
    Call {
        dst: u32,
        func: u32,
        start: u32,
        end: u32,
        outputs: u32,
    },
}

/// How a node depends on the inputs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Class {
    Constant,
    Affine,
    Nonlinear,
}

/// A compiled expression: rows of scalars over the inputs `x[block][offset]`.
///
/// ```
/// use camber_expr::{compile, Names};
/// let mut names = Names::new().with_vector("p", 0).with_vector("q", 1);
/// let affine = compile(&["p - q - [1, 0]"], &mut names)?;       // two rows
/// assert!(affine.is_affine() && affine.rows() == 2);
/// let curved = compile(&["norm(p - q) = 2"], &mut names)?;
/// assert!(!curved.is_affine());
/// let mut out = [0.0_f64];
/// curved.eval(&[&[3.0, 4.0][..], &[0.0, 0.0][..]], &(), &mut out);
/// assert!((out[0] - 3.0).abs() < 1e-15);
/// # Ok::<(), camber_expr::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Program {
    code: Vec<Ins>,
    terms: Vec<(Input, f64)>,
    args: Vec<u32>,
    rows: Vec<u32>,
    registers: usize,
    affine: bool,
    inputs: Vec<Input>,
}

/// Registers kept on the stack during an evaluation; more spill to the heap.
const STACK_REGISTERS: usize = 32;

/// The register file of a small program (most rows a user writes).
const SMALL_REGISTERS: usize = 8;

impl Program {
    /// Finishes a build whose rows are `rows`.
    pub(crate) fn finish(b: Builder, rows: &[Val]) -> Self {
        let out: Vec<Reg> = rows
            .iter()
            .flat_map(|v| match v.ty {
                Type::Scalar => vec![v.regs[0]],
                Type::Vector => vec![v.regs[0], v.regs[1]],
            })
            .collect();
        let n = b.nodes.len();
        let is_const = |r: Reg| b.consts[r as usize].is_some();
        // Which operands each node reads once constants are fused into it.
        let reads = |node: &Node| -> SmallVec<[Reg; 2]> {
            match node {
                Node::Const(_) | Node::Lin { .. } => SmallVec::new(),
                Node::Bin(_, a, c) if is_const(*c) => smallvec::smallvec![*a],
                Node::Bin(_, c, a) if is_const(*c) => smallvec::smallvec![*a],
                Node::Bin(_, a, c) => smallvec::smallvec![*a, *c],
                Node::Fun(_, a) | Node::Powi(a, _) | Node::Output(a, _) => {
                    smallvec::smallvec![*a]
                }
                Node::Call { start, end, .. } => b.args[*start as usize..*end as usize]
                    .iter()
                    .copied()
                    .collect(),
            }
        };
        let mut live = vec![false; n];
        for r in &out {
            live[*r as usize] = true;
        }
        for k in (0..n).rev() {
            if live[k] {
                for r in reads(&b.nodes[k]) {
                    live[r as usize] = true;
                }
            }
        }
        // Affinity, forward.
        let mut class = vec![Class::Constant; n];
        for k in 0..n {
            if !live[k] {
                continue;
            }
            let of = |r: &Reg| class[*r as usize];
            class[k] = match &b.nodes[k] {
                Node::Const(_) => Class::Constant,
                Node::Lin { .. } => Class::Affine,
                Node::Bin(op, a, c) => match op {
                    Bin::Add | Bin::Sub => of(a).max(of(c)),
                    Bin::Mul if of(a) == Class::Constant || of(c) == Class::Constant => {
                        of(a).max(of(c))
                    }
                    Bin::Div if of(c) == Class::Constant => of(a),
                    _ if of(a) == Class::Constant && of(c) == Class::Constant => Class::Constant,
                    _ => Class::Nonlinear,
                },
                Node::Fun(Fun::Neg, a) => of(a),
                Node::Fun(_, a) | Node::Powi(a, _) if of(a) == Class::Constant => Class::Constant,
                Node::Fun(..) | Node::Powi(..) | Node::Call { .. } | Node::Output(..) => {
                    Class::Nonlinear
                }
            };
        }
        let affine = out.iter().all(|r| class[*r as usize] <= Class::Affine);
        // Last reader of each node (rows are read at the end).
        let mut last = vec![0usize; n];
        for (k, node) in b.nodes.iter().enumerate().filter(|(k, _)| live[*k]) {
            for r in reads(node) {
                last[r as usize] = k;
            }
        }
        let mut pinned = vec![false; n];
        for r in &out {
            pinned[*r as usize] = true;
        }
        // Registers.
        let mut reg = vec![u32::MAX; n];
        let mut free: Vec<u32> = Vec::new();
        let mut registers = 0u32;
        let fresh = |count: u32, registers: &mut u32| {
            let r = *registers;
            *registers += count;
            r
        };
        let mut code = Vec::with_capacity(n);
        let mut args = Vec::with_capacity(b.args.len());
        for k in 0..n {
            if !live[k] {
                continue;
            }
            let node = &b.nodes[k];
            if let Node::Output(call, j) = node {
                reg[k] = reg[*call as usize] + j;
                continue;
            }
            let phys = |r: &Reg| reg[*r as usize];
            // The instruction, with its operands' registers read before any is freed.
            let mut ins = match node {
                Node::Const(c) => Ins::Const { dst: 0, value: *c },
                Node::Lin {
                    start,
                    end,
                    constant,
                } => match &b.terms[*start as usize..*end as usize] {
                    // Exactly x: the combination is the input itself.
                    [(input, c)] if (c - 1.0).abs() <= 0.0 && constant.abs() <= 0.0 => Ins::Input {
                        dst: 0,
                        input: *input,
                    },
                    _ => Ins::Lin {
                        dst: 0,
                        start: *start,
                        end: *end,
                        constant: *constant,
                    },
                },
                Node::Bin(op, a, c) => match (b.consts[*a as usize], b.consts[*c as usize]) {
                    (None, Some(value)) => Ins::BinC {
                        dst: 0,
                        op: *op,
                        a: phys(a),
                        c: value,
                    },
                    (Some(value), None) => Ins::CBin {
                        dst: 0,
                        op: *op,
                        c: value,
                        b: phys(c),
                    },
                    _ => Ins::Bin {
                        dst: 0,
                        op: *op,
                        a: phys(a),
                        b: phys(c),
                    },
                },
                Node::Fun(f, a) => Ins::Fun {
                    dst: 0,
                    f: *f,
                    a: phys(a),
                },
                Node::Powi(a, p) => Ins::Powi {
                    dst: 0,
                    a: phys(a),
                    n: *p,
                },
                Node::Call {
                    func,
                    start,
                    end,
                    outputs,
                } => {
                    let s = u32::try_from(args.len()).unwrap_or(u32::MAX);
                    args.extend(b.args[*start as usize..*end as usize].iter().map(phys));
                    let e = u32::try_from(args.len()).unwrap_or(u32::MAX);
                    Ins::Call {
                        dst: 0,
                        func: *func,
                        start: s,
                        end: e,
                        outputs: *outputs,
                    }
                }
                Node::Output(..) => continue,
            };
            // Operands read for the last time give their registers back (a call's outputs
            // and the rows keep theirs).
            let mut done: SmallVec<[Reg; 2]> = reads(node);
            done.dedup();
            for r in done {
                let keep = pinned[r as usize]
                    || matches!(b.nodes[r as usize], Node::Call { .. } | Node::Output(..));
                if last[r as usize] == k && !keep {
                    free.push(reg[r as usize]);
                }
            }
            let dst = match node {
                Node::Call { outputs, .. } => fresh(*outputs, &mut registers),
                _ => free.pop().unwrap_or_else(|| fresh(1, &mut registers)),
            };
            reg[k] = dst;
            set_dst(&mut ins, dst);
            code.push(ins);
        }
        let mut inputs: Vec<Input> = code
            .iter()
            .flat_map(|ins| -> SmallVec<[Input; 4]> {
                match ins {
                    Ins::Input { input, .. } => smallvec::smallvec![*input],
                    Ins::Lin { start, end, .. } => b.terms[*start as usize..*end as usize]
                        .iter()
                        .map(|(i, _)| *i)
                        .collect(),
                    _ => SmallVec::new(),
                }
            })
            .collect();
        inputs.sort_unstable();
        inputs.dedup();
        Self {
            code,
            terms: b.terms,
            args,
            rows: out.iter().map(|r| reg[*r as usize]).collect(),
            registers: registers as usize,
            affine,
            inputs,
        }
    }

    /// The number of rows (a vector row counts two).
    pub fn rows(&self) -> usize {
        self.rows.len()
    }

    /// Whether every row is affine in the inputs (see the module documentation).
    pub fn is_affine(&self) -> bool {
        self.affine
    }

    /// The number of instructions.
    pub fn len(&self) -> usize {
        self.code.len()
    }

    /// Whether there are no instructions (every row a constant read from a register).
    pub fn is_empty(&self) -> bool {
        self.code.is_empty()
    }

    /// The registers an evaluation uses.
    pub fn registers(&self) -> usize {
        self.registers
    }

    /// The inputs read directly (not through the owner's calls), sorted.
    pub fn inputs(&self) -> &[Input] {
        &self.inputs
    }

    /// Writes the rows into `out` (`rows()` entries; extra entries are left alone), reading
    /// `x[block][offset]` (a missing input reads NaN) and calling `ext` for the owner's
    /// functions.
    pub fn eval<T: Scalar, E: Externals + ?Sized>(&self, x: &[&[T]], ext: &E, out: &mut [T]) {
        // The register file in place on the stack, sized to the program (a moved or oversized
        // file costs more than a small expression's arithmetic).
        if self.registers <= SMALL_REGISTERS {
            let mut regs = [T::zero(); SMALL_REGISTERS];
            self.run(x, ext, &mut regs, out);
        } else if self.registers <= STACK_REGISTERS {
            let mut regs = [T::zero(); STACK_REGISTERS];
            self.run(x, ext, &mut regs, out);
        } else {
            let mut regs = vec![T::zero(); self.registers];
            self.run(x, ext, &mut regs, out);
        }
    }

    /// Runs the code on the register file `regs` (at least `registers()` long).
    fn run<T: Scalar, E: Externals + ?Sized>(
        &self,
        x: &[&[T]],
        ext: &E,
        regs: &mut [T],
        out: &mut [T],
    ) {
        for ins in &self.code {
            match *ins {
                Ins::Const { dst, value } => regs[dst as usize] = cst(value),
                Ins::Input { dst, input } => regs[dst as usize] = read(x, input),
                Ins::Lin {
                    dst,
                    start,
                    end,
                    constant,
                } => {
                    regs[dst as usize] =
                        combination(x, &self.terms[start as usize..end as usize], constant);
                }
                Ins::Bin { dst, op, a, b } => {
                    regs[dst as usize] = op.apply(regs[a as usize], regs[b as usize]);
                }
                Ins::BinC { dst, op, a, c } => {
                    regs[dst as usize] = op.apply(regs[a as usize], cst(c));
                }
                Ins::CBin { dst, op, c, b } => {
                    regs[dst as usize] = op.apply(cst(c), regs[b as usize]);
                }
                Ins::Fun { dst, f, a } => regs[dst as usize] = f.apply(regs[a as usize]),
                Ins::Powi { dst, a, n } => regs[dst as usize] = regs[a as usize].powi(n),
                Ins::Call {
                    dst,
                    func,
                    start,
                    end,
                    outputs,
                } => {
                    let a: SmallVec<[T; 2]> = self.args[start as usize..end as usize]
                        .iter()
                        .map(|r| regs[*r as usize])
                        .collect();
                    let (lo, hi) = (dst as usize, (dst + outputs) as usize);
                    ext.call(func, &a, x, &mut regs[lo..hi]);
                }
            }
        }
        for (o, r) in out.iter_mut().zip(&self.rows) {
            *o = regs[*r as usize];
        }
    }
}

/// Σ c·x + k, with unit coefficients as plain additions and subtractions (a product of dual
/// numbers costs as much as any other, whatever the constant).
#[inline]
#[allow(clippy::float_cmp)] // exact on purpose: only a coefficient of exactly ±1 is a plain sum
fn combination<T: Scalar>(x: &[&[T]], terms: &[(Input, f64)], constant: f64) -> T {
    let term = |c: f64, v: T| {
        if c == 1.0 {
            v
        } else if c == -1.0 {
            -v
        } else {
            cst::<T>(c) * v
        }
    };
    let mut s = match terms.first() {
        Some((input, c)) => term(*c, read(x, *input)),
        None => T::zero(),
    };
    for (input, c) in terms.iter().skip(1) {
        let v = read(x, *input);
        if *c == 1.0 {
            s += v;
        } else if *c == -1.0 {
            s -= v;
        } else {
            s += cst::<T>(*c) * v;
        }
    }
    if constant != 0.0 {
        s += cst::<T>(constant);
    }
    s
}

#[inline]
fn read<T: Scalar>(x: &[&[T]], input: Input) -> T {
    x.get(input.block as usize)
        .and_then(|b| b.get(input.offset as usize))
        .copied()
        .unwrap_or_else(|| cst(f64::NAN))
}

fn set_dst(ins: &mut Ins, r: u32) {
    match ins {
        Ins::Const { dst, .. }
        | Ins::Input { dst, .. }
        | Ins::Lin { dst, .. }
        | Ins::Bin { dst, .. }
        | Ins::BinC { dst, .. }
        | Ins::CBin { dst, .. }
        | Ins::Fun { dst, .. }
        | Ins::Powi { dst, .. }
        | Ins::Call { dst, .. } => *dst = r,
    }
}
