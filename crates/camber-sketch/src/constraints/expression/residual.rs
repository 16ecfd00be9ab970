//! The residual of an expression constraint: the compiled tape over the blocks its names read,
//! and the sketch's functions the tape calls (a curve at a varying parameter, an arc length).

use camber_expr::{Externals, Program};
use camber_solve::{Residual, Scalar};
use smallvec::SmallVec;

use crate::constraints::arc_length::LengthOf;
use crate::curve_eval::CurveBasis;

/// A function of the sketch the tape calls.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Function {
    /// C⁽ᵏ⁾(u) of a curve, u the call's one argument (two outputs); `blocks[j]` is the block of
    /// control point j.
    Curve {
        basis: Box<CurveBasis>,
        blocks: Vec<u32>,
        order: usize,
    },
    /// The arc length of a curve (one output), by its fixed quadrature rule.
    Length { rule: LengthOf, blocks: Vec<u32> },
}

/// The sketch's functions, numbered as the tape calls them.
#[derive(Debug, Clone, Default, PartialEq)]
pub(crate) struct Functions(pub(crate) Vec<Function>);

/// The control points of a curve, gathered from the blocks (no allocation up to 16).
fn gather<'a, T>(x: &[&'a [T]], blocks: &[u32]) -> SmallVec<[&'a [T]; 16]> {
    blocks
        .iter()
        .map(|b| x.get(*b as usize).copied().unwrap_or(&[]))
        .collect()
}

impl Externals for Functions {
    fn call<T: Scalar>(&self, func: u32, args: &[T], x: &[&[T]], out: &mut [T]) {
        let nan = camber_solve::scalar::cst::<T>(f64::NAN);
        match self.0.get(func as usize) {
            Some(Function::Curve {
                basis,
                blocks,
                order,
            }) => {
                let points = gather(x, blocks);
                let u = args.first().copied().unwrap_or(nan);
                let d = basis.eval2(&points, u);
                let c = d.get(*order).copied().unwrap_or([nan, nan]);
                for (o, v) in out.iter_mut().zip(c) {
                    *o = v;
                }
            }
            Some(Function::Length { rule, blocks }) => {
                let points = gather(x, blocks);
                let mut g = [T::zero()];
                rule.eval(&points, &mut g);
                if let Some(o) = out.first_mut() {
                    *o = g[0];
                }
            }
            None => out.fill(nan),
        }
    }
}

/// An expression constraint's rows as a residual over its blocks (points, radii, its own free
/// parameters), generic over the scalar type like every built-in residual.
#[derive(Debug, Clone, PartialEq)]
pub struct ExpressionResidual {
    name: String,
    program: Program,
    functions: Functions,
    sizes: Vec<usize>,
}

impl ExpressionResidual {
    pub(crate) fn new(
        name: String,
        program: Program,
        functions: Functions,
        sizes: Vec<usize>,
    ) -> Self {
        Self {
            name,
            program,
            functions,
            sizes,
        }
    }

    /// The compiled rows.
    pub fn program(&self) -> &Program {
        &self.program
    }
}

impl Residual for ExpressionResidual {
    fn name(&self) -> &str {
        if self.name.is_empty() {
            "expression"
        } else {
            &self.name
        }
    }
    fn dim(&self) -> usize {
        self.program.rows()
    }
    fn block_sizes(&self) -> Option<Vec<usize>> {
        Some(self.sizes.clone())
    }
    fn accepts_block_sizes(&self, sizes: &[usize]) -> bool {
        sizes == self.sizes.as_slice()
    }
    fn is_affine(&self) -> bool {
        self.program.is_affine()
    }
    fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) {
        self.program.eval(x, &self.functions, out);
    }
}
