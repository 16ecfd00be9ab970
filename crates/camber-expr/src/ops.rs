//! The scalar operations of the tape and the built-in functions of the language, each written
//! once generically over [`Scalar`], so that folding a constant (f64), evaluating values and
//! evaluating dual numbers run the same arithmetic.

use camber_scalar::Scalar;

use crate::types::Type;

/// A binary operation on two scalars.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub(crate) enum Bin {
    Add,
    Sub,
    Mul,
    Div,
    /// a^b for a varying exponent: exp(b·ln a).
    Pow,
    Atan2,
}

impl Bin {
    #[inline]
    pub(crate) fn apply<T: Scalar>(self, a: T, b: T) -> T {
        match self {
            Bin::Add => a + b,
            Bin::Sub => a - b,
            Bin::Mul => a * b,
            Bin::Div => a / b,
            Bin::Pow => a.powf(b),
            Bin::Atan2 => a.atan2(b),
        }
    }
}

/// A function of one scalar.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub(crate) enum Fun {
    Neg,
    Sqrt,
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Exp,
    Ln,
    Abs,
}

impl Fun {
    #[inline]
    pub(crate) fn apply<T: Scalar>(self, a: T) -> T {
        match self {
            Fun::Neg => -a,
            Fun::Sqrt => a.sqrt(),
            Fun::Sin => a.sin(),
            Fun::Cos => a.cos(),
            Fun::Tan => a.tan(),
            Fun::Asin => a.asin(),
            Fun::Acos => a.acos(),
            Fun::Atan => a.atan(),
            Fun::Exp => a.exp(),
            Fun::Ln => a.ln(),
            Fun::Abs => a.abs(),
        }
    }
}

/// What a built-in function does with its arguments.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Builtin {
    /// A scalar function of a scalar.
    Scalar(Fun),
    /// atan2(y, x).
    Atan2,
    /// dot(a, b) = aₓbₓ + a_yb_y.
    Dot,
    /// cross(a, b) = aₓb_y − a_ybₓ.
    Cross,
    /// norm(a) = √(a·a).
    Norm,
    /// perp(a) = (−a_y, aₓ), a turned a quarter counter-clockwise.
    Perp,
    /// unit(a) = a/‖a‖.
    Unit,
    /// angle(a, b) = atan2(cross(a, b), dot(a, b)), from a to b counter-clockwise.
    Angle,
    /// vec(x, y).
    Vec,
    /// hypot(a, b) = √(a² + b²).
    Hypot,
}

/// Every built-in function: name, what it does, its argument types, its result type, and a
/// line of documentation (the language reference is generated from this table).
pub const FUNCTIONS: &[(&str, &[Type], Type, &str)] = &[
    ("sqrt", &[Type::Scalar], Type::Scalar, "square root"),
    ("sin", &[Type::Scalar], Type::Scalar, "sine (radians)"),
    ("cos", &[Type::Scalar], Type::Scalar, "cosine (radians)"),
    ("tan", &[Type::Scalar], Type::Scalar, "tangent (radians)"),
    ("asin", &[Type::Scalar], Type::Scalar, "arc sine"),
    ("acos", &[Type::Scalar], Type::Scalar, "arc cosine"),
    ("atan", &[Type::Scalar], Type::Scalar, "arc tangent"),
    (
        "atan2",
        &[Type::Scalar, Type::Scalar],
        Type::Scalar,
        "atan2(y, x): the angle of (x, y)",
    ),
    ("exp", &[Type::Scalar], Type::Scalar, "e to the power"),
    ("ln", &[Type::Scalar], Type::Scalar, "natural logarithm"),
    (
        "abs",
        &[Type::Scalar],
        Type::Scalar,
        "absolute value (not smooth at 0: prefer squares)",
    ),
    (
        "hypot",
        &[Type::Scalar, Type::Scalar],
        Type::Scalar,
        "√(a² + b²)",
    ),
    (
        "dot",
        &[Type::Vector, Type::Vector],
        Type::Scalar,
        "dot product aₓbₓ + a_y b_y",
    ),
    (
        "cross",
        &[Type::Vector, Type::Vector],
        Type::Scalar,
        "planar cross product aₓb_y − a_y bₓ",
    ),
    ("norm", &[Type::Vector], Type::Scalar, "length √(a·a)"),
    ("unit", &[Type::Vector], Type::Vector, "a / norm(a)"),
    (
        "perp",
        &[Type::Vector],
        Type::Vector,
        "(−a_y, aₓ): a turned a quarter turn counter-clockwise",
    ),
    (
        "angle",
        &[Type::Vector, Type::Vector],
        Type::Scalar,
        "the angle from a to b, counter-clockwise, in (−π, π]",
    ),
    (
        "vec",
        &[Type::Scalar, Type::Scalar],
        Type::Vector,
        "the vector (x, y), also written [x, y]",
    ),
];

/// The built-in constants.
pub const CONSTANTS: &[(&str, f64)] = &[("pi", std::f64::consts::PI)];

/// The built-in function of that name.
pub(crate) fn builtin(name: &str) -> Option<(Builtin, &'static [Type], Type)> {
    let b = match name {
        "sqrt" => Builtin::Scalar(Fun::Sqrt),
        "sin" => Builtin::Scalar(Fun::Sin),
        "cos" => Builtin::Scalar(Fun::Cos),
        "tan" => Builtin::Scalar(Fun::Tan),
        "asin" => Builtin::Scalar(Fun::Asin),
        "acos" => Builtin::Scalar(Fun::Acos),
        "atan" => Builtin::Scalar(Fun::Atan),
        "exp" => Builtin::Scalar(Fun::Exp),
        "ln" => Builtin::Scalar(Fun::Ln),
        "abs" => Builtin::Scalar(Fun::Abs),
        "atan2" => Builtin::Atan2,
        "hypot" => Builtin::Hypot,
        "dot" => Builtin::Dot,
        "cross" => Builtin::Cross,
        "norm" => Builtin::Norm,
        "unit" => Builtin::Unit,
        "perp" => Builtin::Perp,
        "angle" => Builtin::Angle,
        "vec" => Builtin::Vec,
        _ => return None,
    };
    FUNCTIONS
        .iter()
        .find(|(n, ..)| *n == name)
        .map(|(_, args, result, _)| (b, *args, *result))
}

/// Whether a name is taken by the language (a built-in function or constant): the owner of
/// the names may not define it.
///
/// ```
/// assert!(camber_expr::is_reserved("dot") && camber_expr::is_reserved("pi"));
/// assert!(!camber_expr::is_reserved("chord"));
/// ```
pub fn is_reserved(name: &str) -> bool {
    FUNCTIONS.iter().any(|(n, ..)| *n == name) || CONSTANTS.iter().any(|(n, _)| *n == name)
}
