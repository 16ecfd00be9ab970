//! Why an expression was refused: every error names the column (1-based, in characters) where
//! the offending part starts, and what was wrong there.

use crate::types::Type;

/// An expression error. Columns count characters from 1; an error about the whole text (its
/// length) has none.
///
/// ```
/// use camber_expr::{compile, Error, Names};
/// let names = Names::new().with_scalar("a", 0, 0);
/// assert_eq!(compile(&["a +"], &mut names.clone()).unwrap_err().column(), Some(4));
/// assert!(matches!(compile(&["b"], &mut names.clone()), Err(Error::UnknownName { column: 1, .. })));
/// ```
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// The text does not follow the grammar.
    ///
    /// ```
    /// # use camber_expr::{compile, Error, Names};
    /// let e = compile(&["(1 + 2"], &mut Names::new()).unwrap_err();
    /// assert_eq!(e.to_string(), "column 7: expected `)`, found the end of the expression");
    /// ```
    #[error("column {column}: expected {expected}, found {found}")]
    Syntax {
        /// Where.
        column: usize,
        /// What the grammar allows there.
        expected: String,
        /// What is there (a quoted piece of text, or "the end of the expression").
        found: String,
    },
    /// A name that is neither a built-in function or constant nor one of the names given.
    ///
    /// ```
    /// # use camber_expr::{compile, Error, Names};
    /// let e = compile(&["1 + chrod"], &mut Names::new()).unwrap_err();
    /// assert_eq!(e.to_string(), "column 5: unknown name `chrod`");
    /// ```
    #[error("column {column}: unknown name `{name}`")]
    UnknownName {
        /// Where.
        column: usize,
        /// The name.
        name: String,
    },
    /// An operator or function given a scalar where it needs a vector, or the reverse.
    ///
    /// ```
    /// # use camber_expr::{compile, Error, Names};
    /// let names = Names::new().with_vector("p", 0);
    /// let e = compile(&["sqrt(p)"], &mut names.clone()).unwrap_err();
    /// assert_eq!(e.to_string(), "column 6: `sqrt` needs a scalar, found a vector");
    /// ```
    #[error("column {column}: {what} needs {expected}, found {found}")]
    Type {
        /// Where the offending operand starts.
        column: usize,
        /// The operator or function (quoted).
        what: String,
        /// The type it needs (with its article).
        expected: TypeWord,
        /// The type it got.
        found: TypeWord,
    },
    /// A function called with the wrong number of arguments.
    ///
    /// ```
    /// # use camber_expr::{compile, Error, Names};
    /// let e = compile(&["atan2(1)"], &mut Names::new()).unwrap_err();
    /// assert_eq!(e.to_string(), "column 1: `atan2` takes 2 arguments, found 1");
    /// ```
    #[error("column {column}: `{function}` takes {expected} argument{}, found {found}", plural(*expected))]
    Arity {
        /// Where the call starts.
        column: usize,
        /// The function.
        function: String,
        /// How many it takes.
        expected: usize,
        /// How many it got.
        found: usize,
    },
    /// A division whose divisor is a constant equal to zero.
    ///
    /// ```
    /// # use camber_expr::{compile, Error, Names};
    /// let e = compile(&["1 / (2 - 2)"], &mut Names::new()).unwrap_err();
    /// assert_eq!(e.to_string(), "column 5: division by a constant zero");
    /// ```
    #[error("column {column}: division by a constant zero")]
    DivisionByZero {
        /// Where the divisor starts.
        column: usize,
    },
    /// A constant part that is not a finite number (`sqrt(-1)`, `ln(0)`, `1e999`, a NaN
    /// parameter).
    ///
    /// ```
    /// # use camber_expr::{compile, Error, Names};
    /// let e = compile(&["sqrt(-1)"], &mut Names::new()).unwrap_err();
    /// assert_eq!(e.to_string(), "column 1: the constant value is not finite (NaN)");
    /// ```
    #[error("column {column}: the constant value is not finite ({value})")]
    NonFinite {
        /// Where the constant part starts.
        column: usize,
        /// Its value.
        value: f64,
    },
    /// A text longer than [`crate::MAX_EXPRESSION_BYTES`], refused before it is read.
    ///
    /// ```
    /// # use camber_expr::{compile, Error, Names};
    /// let long = "1+".repeat(600_000) + "1";
    /// assert!(matches!(compile(&[long.as_str()], &mut Names::new()), Err(Error::TooLong { .. })));
    /// ```
    #[error("the expression is {bytes} bytes long, more than the {max} allowed")]
    TooLong {
        /// Its length.
        bytes: usize,
        /// The limit.
        max: usize,
    },
    /// Brackets nested deeper than [`crate::MAX_DEPTH`], refused before the text is parsed.
    ///
    /// ```
    /// # use camber_expr::{compile, Error, Names};
    /// let deep = "(".repeat(100) + "1" + &")".repeat(100);
    /// let e = compile(&[deep.as_str()], &mut Names::new()).unwrap_err();
    /// assert_eq!(e.to_string(), "column 65: brackets nested more than 64 deep");
    /// ```
    #[error("column {column}: brackets nested more than {max} deep")]
    TooDeep {
        /// The first bracket past the limit.
        column: usize,
        /// The limit.
        max: usize,
    },
    /// A compiled expression larger than [`crate::MAX_TAPE`] operations (a long text of curve
    /// evaluations, each a combination of many control points).
    ///
    /// ```
    /// # use camber_expr::{compile, Error, Names};
    /// let names = Names::new().with_scalar("a", 0, 0);
    /// // Each row within the text limit, each a different sum of 16,000 terms.
    /// let many: Vec<String> = (1..=20).map(|r| format!("{r}*a+") + &"a*a+".repeat(16_000) + "a").collect();
    /// let rows: Vec<&str> = many.iter().map(String::as_str).collect();
    /// assert!(matches!(compile(&rows, &mut names.clone()), Err(Error::TooLarge { .. })));
    /// ```
    #[error("the compiled expression needs more than {max} operations")]
    TooLarge {
        /// The limit.
        max: usize,
    },
    /// No rows, or more than [`crate::MAX_ROWS`].
    ///
    /// ```
    /// # use camber_expr::{compile, Error, Names};
    /// assert_eq!(compile(&[], &mut Names::new()).unwrap_err().to_string(),
    ///            "an expression constraint has 0 rows, expected 1 to 64");
    /// ```
    #[error("an expression constraint has {found} rows, expected 1 to {max}")]
    RowCount {
        /// How many rows there are.
        found: usize,
        /// The limit.
        max: usize,
    },
    /// An error in one row of an expression of several rows (rows count from 1).
    ///
    /// ```
    /// # use camber_expr::{compile, Error, Names};
    /// let e = compile(&["1", "2 +"], &mut Names::new()).unwrap_err();
    /// assert_eq!(e.to_string(), "row 2: column 4: expected an operand (a number, a name, `(` or `[`), found the end of the expression");
    /// assert_eq!((e.row(), e.column()), (Some(2), Some(4)));
    /// ```
    #[error("row {row}: {error}")]
    InRow {
        /// The row, from 1.
        row: usize,
        /// The error in it.
        error: Box<Error>,
    },
    /// What the names' owner refused (a parameter outside a curve's domain, an unknown
    /// member of an object).
    ///
    /// ```
    /// # use camber_expr::{compile, Error, Names};
    /// let names = Names::new().with_vector("p", 0);
    /// let e = compile(&["p.z"], &mut names.clone()).unwrap_err();
    /// assert_eq!(e.to_string(), "column 3: a vector has the members `x` and `y`, not `z`");
    /// ```
    #[error("column {column}: {message}")]
    Scope {
        /// Where the offending part starts.
        column: usize,
        /// The owner's message.
        message: String,
    },
}

impl Error {
    /// The column the error points at (`None` for an error about the whole text).
    pub fn column(&self) -> Option<usize> {
        match self {
            Error::Syntax { column, .. }
            | Error::UnknownName { column, .. }
            | Error::Type { column, .. }
            | Error::Arity { column, .. }
            | Error::DivisionByZero { column }
            | Error::NonFinite { column, .. }
            | Error::TooDeep { column, .. }
            | Error::Scope { column, .. } => Some(*column),
            Error::InRow { error, .. } => error.column(),
            Error::TooLong { .. } | Error::TooLarge { .. } | Error::RowCount { .. } => None,
        }
    }

    /// The row (1-based) the error is in, for an expression of several rows.
    pub fn row(&self) -> Option<usize> {
        match self {
            Error::InRow { row, .. } => Some(*row),
            _ => None,
        }
    }

    /// The error without the row it is in.
    pub fn innermost(&self) -> &Error {
        match self {
            Error::InRow { error, .. } => error.innermost(),
            other => other,
        }
    }
}

/// A type as an error message says it ("a scalar", "a vector").
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TypeWord(pub Type);

impl std::fmt::Display for TypeWord {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self.0 {
            Type::Scalar => "a scalar",
            Type::Vector => "a vector",
        })
    }
}

fn plural(n: usize) -> &'static str {
    if n == 1 {
        ""
    } else {
        "s"
    }
}

/// `Result<T, Error>`.
pub type Result<T> = std::result::Result<T, Error>;
