//! The owner of the names an expression reads ([`Scope`]), the owner's functions at evaluation
//! time ([`Externals`]), and [`Names`], a plain scope of scalars, vectors and constants.

use std::collections::BTreeMap;

use camber_scalar::Scalar;

use crate::types::{CallArg, Input, Term, Value};

/// The owner of the names an expression reads, asked while it is compiled.
///
/// Each method answers `Ok(None)` for a name it does not know (the compiler then reports an
/// unknown name at its column), or `Err(message)` for a name it knows used wrongly (the
/// message is reported at the column of the use).
pub trait Scope {
    /// The value of a plain name (`chord`, `P`).
    ///
    /// # Errors
    /// The owner's message.
    fn value(&mut self, name: &str) -> Result<Option<Value>, String>;

    /// A member of an object that has no value of its own (`K.radius`, `L.dir`). Members
    /// `x` and `y` of a vector are the compiler's.
    ///
    /// # Errors
    /// The owner's message (an unknown member, say).
    fn member(&mut self, name: &str, member: &str) -> Result<Option<Value>, String> {
        let _ = (name, member);
        Ok(None)
    }

    /// A call of an object: `name` with `primes` primes (`C''(u)` has two) on `args`.
    ///
    /// # Errors
    /// The owner's message (a parameter outside a domain, a wrong argument).
    fn call(
        &mut self,
        name: &str,
        primes: usize,
        args: &[CallArg],
    ) -> Result<Option<Value>, String> {
        let _ = (name, primes, args);
        Ok(None)
    }
}

/// The owner's functions, called by the tape at evaluation time for [`Term::Call`] values.
pub trait Externals {
    /// Writes the outputs of function `func` on `args` into `out`, reading the inputs `x`.
    fn call<T: Scalar>(&self, func: u32, args: &[T], x: &[&[T]], out: &mut [T]);
}

/// No functions: every call gives NaN.
impl Externals for () {
    fn call<T: Scalar>(&self, _func: u32, _args: &[T], _x: &[&[T]], out: &mut [T]) {
        out.fill(camber_scalar::cst(f64::NAN));
    }
}

/// A plain scope: named scalars and vectors read from the inputs, and named constants.
///
/// ```
/// use camber_expr::{compile, Names};
/// let mut names = Names::new().with_vector("p", 0).with_scalar("r", 1, 0).with_constant("k", 2.0);
/// let program = compile(&["dot(p, p) - k * r^2"], &mut names)?;
/// let mut out = [0.0_f64];
/// program.eval(&[&[3.0, 4.0][..], &[2.0][..]], &(), &mut out);
/// assert!((out[0] - 17.0).abs() < 1e-15);
/// # Ok::<(), camber_expr::Error>(())
/// ```
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Names {
    values: BTreeMap<String, Value>,
}

impl Names {
    /// No names.
    pub fn new() -> Self {
        Self::default()
    }

    /// `name` is the scalar `x[block][offset]`.
    pub fn with_scalar(mut self, name: &str, block: usize, offset: usize) -> Self {
        self.values.insert(
            name.to_owned(),
            Value::Scalar(Term::input(Input::new(block, offset))),
        );
        self
    }

    /// `name` is the vector (`x[block][0]`, `x[block][1]`).
    pub fn with_vector(mut self, name: &str, block: usize) -> Self {
        self.values.insert(
            name.to_owned(),
            Value::Vector([
                Term::input(Input::new(block, 0)),
                Term::input(Input::new(block, 1)),
            ]),
        );
        self
    }

    /// `name` is the constant `value`.
    pub fn with_constant(mut self, name: &str, value: f64) -> Self {
        self.values
            .insert(name.to_owned(), Value::Scalar(Term::Const(value)));
        self
    }

    /// `name` is `value`.
    pub fn with_value(mut self, name: &str, value: Value) -> Self {
        self.values.insert(name.to_owned(), value);
        self
    }
}

impl Scope for Names {
    fn value(&mut self, name: &str) -> Result<Option<Value>, String> {
        Ok(self.values.get(name).cloned())
    }
}
