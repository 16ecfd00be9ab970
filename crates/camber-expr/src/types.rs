//! The two value types of the language, and what a name stands for: the vocabulary between
//! the compiler and the owner of the names ([`crate::Scope`]).

/// The type of a value: a real number or a planar vector.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Type {
    /// One real number.
    Scalar,
    /// A planar vector (x, y).
    Vector,
}

/// One number of the evaluation input: component `offset` of block `block` (the residual's
/// `x[block][offset]`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Input {
    /// The block.
    pub block: u32,
    /// The component inside it.
    pub offset: u32,
}

impl Input {
    /// Component `offset` of block `block`.
    pub fn new(block: usize, offset: usize) -> Self {
        // Blocks and offsets are counts of a problem's slots, far below 2³².
        Self {
            block: u32::try_from(block).unwrap_or(u32::MAX),
            offset: u32::try_from(offset).unwrap_or(u32::MAX),
        }
    }
}

/// What one number of a name's value is, as its owner defines it.
#[derive(Debug, Clone, PartialEq)]
pub enum Term {
    /// A constant (a fixed parameter, a datum).
    Const(f64),
    /// Σ c·x + k over inputs: a point, a control point, a curve point at a fixed parameter.
    Linear {
        /// (input, coefficient) pairs.
        terms: Vec<(Input, f64)>,
        /// The constant k.
        constant: f64,
    },
    /// Output `output` of the owner's function `func` ([`crate::Externals::call`]) applied to
    /// the call's arguments: a curve point at a free parameter, an arc length.
    Call {
        /// The owner's function number.
        func: u32,
        /// Which of its outputs.
        output: u32,
        /// How many outputs it writes.
        outputs: u32,
    },
}

impl Term {
    /// The input itself.
    pub fn input(input: Input) -> Self {
        Term::Linear {
            terms: vec![(input, 1.0)],
            constant: 0.0,
        }
    }
}

/// What a name, a member or a call of the owner stands for: a scalar or a vector of terms.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// A scalar.
    Scalar(Term),
    /// A vector (x, y).
    Vector([Term; 2]),
}

impl Value {
    /// Its type.
    pub fn ty(&self) -> Type {
        match self {
            Value::Scalar(_) => Type::Scalar,
            Value::Vector(_) => Type::Vector,
        }
    }
}

/// An argument of a call to the owner's object (`C(u)`): a constant, known when the
/// expression is compiled, or a value that varies with the inputs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CallArg {
    /// A constant (the owner may expand the call, a curve point at a fixed parameter being
    /// linear in the control points).
    Const(f64),
    /// A varying scalar (the call becomes a [`Term::Call`]); when the argument is exactly one
    /// input (`C(s)` for a free parameter s), that input.
    Varying(Option<Input>),
    /// A vector (constant or not).
    Vector,
}
