//! camber-expr: expressions over scalars and planar vectors, compiled once to a flat tape that
//! evaluates generically over [`camber_scalar::Scalar`], so values (f64), exact Jacobians
//! (dual numbers) and Hessians (hyper-dual numbers) all come from one program.
//!
//! ```
//! use camber_expr::{compile, Names};
//! // p and q are points (blocks 0 and 1 of the input), r a scalar (block 2).
//! let mut names = Names::new().with_vector("p", 0).with_vector("q", 1).with_scalar("r", 2, 0);
//! let program = compile(&["norm(p - q) = 2 * r", "cross(p, q)"], &mut names)?;
//! assert_eq!(program.rows(), 2);
//! assert!(!program.is_affine());
//! let mut out = [0.0_f64; 2];
//! program.eval(&[&[3.0, 0.0][..], &[0.0, 4.0][..], &[2.0][..]], &(), &mut out);
//! assert!((out[0] - 1.0).abs() < 1e-15 && (out[1] - 12.0).abs() < 1e-15);
//!
//! // Errors point at the column.
//! let e = compile(&["norm(p) + q"], &mut names).unwrap_err();
//! assert_eq!(e.to_string(), "column 11: `+` needs a scalar, found a vector");
//! # Ok::<(), camber_expr::Error>(())
//! ```
//!
//! # Usage
//! The language has two types, scalars and vectors (x, y); `+ - * / ^` (also `**`), unary
//! minus, brackets, vector literals `[x, y]`, members `.x` and `.y`, a top-level `a = b` (the
//! row a − b), the constant `pi`, and the functions of [`FUNCTIONS`] (`sqrt`, `sin`, `cos`,
//! `atan2`, `dot`, `cross`, `norm`, …). A vector row gives two rows. Every other name belongs
//! to a [`Scope`]: [`Names`] binds names to inputs and constants; camber-sketch binds the
//! sketch's points, curves (`C(u)`, `C'(u)`, `C''(u)`), circles, lines and parameters.
//!
//! # Design
//! - **Bounded before work** ([`limits`]): a row's length and bracket depth are checked by one
//!   scan before parsing; the parser recurses on brackets only.
//! - **One pass, no tree** (`parse`): the parser (numbers, names and spaces read with
//!   winnow) writes single-assignment nodes as it reads, checking types and arities and folding
//!   constants on the way, so every error has the column of its cause, and a constant that is
//!   not finite, or a constant zero divisor, is refused where it is written.
//! - **A flat tape** ([`Program`]): dead nodes dropped, constants fused into their
//!   instructions, registers reused; evaluation is one loop over instructions, generic over
//!   the scalar type, with no allocation for small programs. Affinity is read from the nodes.
//!
//! This crate knows nothing of sketches: the owner of the names supplies values as
//! combinations of inputs ([`Term`]) and, for what is not linear (a curve at a varying
//! parameter), functions of its own ([`Externals`]).

mod builder;
pub mod errors;
pub mod limits;
mod ops;
mod parse;
mod scope;
mod tape;
mod types;

pub use errors::{Error, Result};
pub use limits::{MAX_DEPTH, MAX_EXPRESSION_BYTES, MAX_ROWS, MAX_TAPE};
pub use ops::{is_reserved, CONSTANTS, FUNCTIONS};
pub use scope::{Externals, Names, Scope};
pub use tape::Program;
pub use types::{CallArg, Input, Term, Type, Value};

/// Compiles rows of expression text over the names of `scope` into one [`Program`].
///
/// Each row is checked for length and nesting before it is read
/// ([`MAX_EXPRESSION_BYTES`], [`MAX_DEPTH`]); there must be 1 to [`MAX_ROWS`] rows.
///
/// # Errors
/// The first error found, with its column ([`Error`]); in an expression of several rows it
/// is wrapped in [`Error::InRow`].
pub fn compile<S: Scope + ?Sized>(rows: &[&str], scope: &mut S) -> Result<Program> {
    if rows.is_empty() || rows.len() > MAX_ROWS {
        return Err(Error::RowCount {
            found: rows.len(),
            max: MAX_ROWS,
        });
    }
    let several = rows.len() > 1;
    // The compiled size is the whole expression's, not one row's.
    let in_row = |k: usize, e: Error| {
        if several && !matches!(e, Error::TooLarge { .. }) {
            Error::InRow {
                row: k + 1,
                error: Box::new(e),
            }
        } else {
            e
        }
    };
    for (k, text) in rows.iter().enumerate() {
        limits::prescan(text).map_err(|e| in_row(k, e))?;
    }
    let mut b = builder::Builder::default();
    let mut vals = Vec::with_capacity(rows.len());
    for (k, text) in rows.iter().enumerate() {
        b.columns = builder::Columns::new(text);
        let mut rest: &str = text;
        let v = parse::Reader::new(text, &mut b, scope)
            .row(&mut rest)
            .map_err(|e| in_row(k, e))?;
        vals.push(v);
    }
    Ok(Program::finish(b, &vals))
}
