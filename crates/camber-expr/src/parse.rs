//! The grammar, read in one pass that writes the tape as it goes (no syntax tree, so nothing
//! recurses over a long sum or a chain of powers; only brackets nest, at most
//! [`crate::MAX_DEPTH`] deep).
//!
//! ```text
//! row      = sum [ "=" sum ]                      a = b is the row a − b
//! sum      = product { ("+" | "-") product }
//! product  = unary { ("*" | "/") unary }
//! unary    = { "-" | "+" } power                  −x^2 is −(x²)
//! power    = postfix { ("^" | "**") { "-" | "+" } postfix }    right-associative
//! postfix  = primary { "." name }                 p.x, p.y
//! primary  = number | "(" sum ")" | "[" sum "," sum "]"
//!          | name { "'" } "(" [ sum { "," sum } ] ")"   f(x), C(u), C'(u), C''(u)
//!          | name [ "." name ]                    chord, P, K.radius
//! ```
//!
//! Numbers, names and spaces are read with winnow's parsers; precedence is the loop above.

use winnow::ascii::{float, multispace0};
use winnow::error::ContextError;
use winnow::token::take_while;
use winnow::Parser as _;

use crate::builder::{Builder, Reg, Val};
use crate::errors::{Error, Result};
use crate::ops::{builtin, Bin, Builtin, Fun, CONSTANTS};
use crate::scope::Scope;
use crate::types::{CallArg, Type};
use crate::MAX_DEPTH;

/// The reader of one row's text, writing into a builder shared by all rows.
pub(crate) struct Reader<'t, 'b, S: Scope + ?Sized> {
    text: &'t str,
    pub(crate) b: &'b mut Builder,
    scope: &'b mut S,
    depth: usize,
}

fn ws(i: &mut &str) {
    let _ = multispace0::<_, ContextError>.parse_next(i);
}

fn is_name_start(c: char) -> bool {
    c.is_ascii_alphabetic() || c == '_'
}

fn is_name_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

impl<'t, 'b, S: Scope + ?Sized> Reader<'t, 'b, S> {
    pub(crate) fn new(text: &'t str, b: &'b mut Builder, scope: &'b mut S) -> Self {
        Self {
            text,
            b,
            scope,
            depth: 0,
        }
    }

    fn at(&self, i: &str) -> usize {
        self.text.len() - i.len()
    }

    fn col(&self, i: &str) -> usize {
        self.b.col(self.at(i))
    }

    /// What is at `i`, for an error message.
    fn found(i: &str) -> String {
        match i.chars().next() {
            None => "the end of the expression".into(),
            Some(c) if is_name_char(c) || c == '.' => {
                let run: String = i
                    .chars()
                    .take_while(|c| is_name_char(*c) || *c == '.')
                    .take(24)
                    .collect();
                format!("`{run}`")
            }
            Some(c) => format!("`{c}`"),
        }
    }

    fn syntax(&self, i: &str, expected: &str) -> Error {
        Error::Syntax {
            column: self.col(i),
            expected: expected.into(),
            found: Self::found(i),
        }
    }

    /// Consumes `token` (after spaces) when it is next.
    fn eat(i: &mut &str, token: &str) -> bool {
        ws(i);
        match i.strip_prefix(token) {
            Some(rest) => {
                *i = rest;
                true
            }
            None => false,
        }
    }

    fn expect(&self, i: &mut &str, token: &str) -> Result<()> {
        if Self::eat(i, token) {
            Ok(())
        } else {
            Err(self.syntax(i, &format!("`{token}`")))
        }
    }

    fn enter(&mut self, i: &str) -> Result<()> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(Error::TooDeep {
                column: self.col(i),
                max: MAX_DEPTH,
            });
        }
        Ok(())
    }

    /// A whole row: `sum [= sum]`, then the end of the text.
    pub(crate) fn row(&mut self, i: &mut &str) -> Result<Val> {
        let lhs = self.sum(i)?;
        ws(i);
        let v = if i.starts_with('=') && !i.starts_with("==") {
            let eq = self.at(i);
            *i = &i[1..];
            let rhs = self.sum(i)?;
            let mut v = self.arith(Bin::Sub, lhs, rhs, "`=`")?;
            v.at = lhs.at.min(eq);
            v
        } else {
            lhs
        };
        ws(i);
        if i.is_empty() {
            Ok(v)
        } else {
            Err(self.syntax(i, "an operator or the end of the expression"))
        }
    }

    fn sum(&mut self, i: &mut &str) -> Result<Val> {
        let mut acc = self.product(i)?;
        loop {
            ws(i);
            let (op, what) = match i.chars().next() {
                Some('+') => (Bin::Add, "`+`"),
                Some('-') => (Bin::Sub, "`-`"),
                _ => return Ok(acc),
            };
            *i = &i[1..];
            let rhs = self.product(i)?;
            acc = self.arith(op, acc, rhs, what)?;
        }
    }

    fn product(&mut self, i: &mut &str) -> Result<Val> {
        let mut acc = self.unary(i)?;
        loop {
            ws(i);
            let op = if i.starts_with("**") {
                return Ok(acc);
            } else if i.starts_with('*') {
                Bin::Mul
            } else if i.starts_with('/') {
                Bin::Div
            } else {
                return Ok(acc);
            };
            *i = &i[1..];
            let rhs = self.unary(i)?;
            acc = if op == Bin::Mul {
                self.mul(acc, rhs)?
            } else {
                self.div(acc, rhs)?
            };
        }
    }

    /// Signs before an operand: whether they negate it.
    fn signs(i: &mut &str) -> bool {
        let mut negate = false;
        loop {
            ws(i);
            match i.chars().next() {
                Some('-') => negate = !negate,
                Some('+') => {}
                _ => return negate,
            }
            *i = &i[1..];
        }
    }

    fn unary(&mut self, i: &mut &str) -> Result<Val> {
        ws(i);
        let at = self.at(i);
        let negate = Self::signs(i);
        let v = self.power(i)?;
        if negate {
            let mut n = self.neg(v)?;
            n.at = at;
            Ok(n)
        } else {
            Ok(v)
        }
    }

    fn power(&mut self, i: &mut &str) -> Result<Val> {
        let base = self.postfix(i)?;
        let mut chain: Vec<(bool, Val)> = Vec::new();
        loop {
            ws(i);
            if let Some(rest) = i.strip_prefix("**") {
                *i = rest;
            } else if let Some(rest) = i.strip_prefix('^') {
                *i = rest;
            } else {
                break;
            }
            let negate = Self::signs(i);
            chain.push((negate, self.postfix(i)?));
        }
        // a ^ b ^ c is a ^ (b ^ c): fold from the right.
        let Some((negate, last)) = chain.pop() else {
            return Ok(base);
        };
        let mut e = if negate { self.neg(last)? } else { last };
        while let Some((negate, v)) = chain.pop() {
            let p = self.pow(v, e)?;
            e = if negate { self.neg(p)? } else { p };
        }
        self.pow(base, e)
    }

    fn postfix(&mut self, i: &mut &str) -> Result<Val> {
        let mut v = self.primary(i)?;
        loop {
            ws(i);
            let Some(rest) = i.strip_prefix('.') else {
                return Ok(v);
            };
            let member_at = self.at(rest);
            let mut r = rest;
            let name = self.name(&mut r)?;
            *i = r;
            if v.ty != Type::Vector {
                return Err(Error::Type {
                    column: self.b.col(v.at),
                    what: format!("`.{name}`"),
                    expected: crate::errors::TypeWord(Type::Vector),
                    found: crate::errors::TypeWord(v.ty),
                });
            }
            let k = match name {
                "x" => 0,
                "y" => 1,
                _ => {
                    return Err(Error::Scope {
                        column: self.b.col(member_at),
                        message: format!("a vector has the members `x` and `y`, not `{name}`"),
                    })
                }
            };
            v = Builder::scalar(v.regs[k], v.at);
        }
    }

    fn name<'i>(&self, i: &mut &'i str) -> Result<&'i str> {
        match i.chars().next() {
            Some(c) if is_name_start(c) => {}
            _ => return Err(self.syntax(i, "a name")),
        }
        take_while::<_, _, ContextError>(1.., is_name_char)
            .parse_next(i)
            .map_err(|_| self.syntax(i, "a name"))
    }

    fn primary(&mut self, i: &mut &str) -> Result<Val> {
        ws(i);
        let at = self.at(i);
        let mut chars = i.chars();
        match (chars.next(), chars.next()) {
            (Some(c), _) if c.is_ascii_digit() => self.number(i),
            (Some('.'), Some(d)) if d.is_ascii_digit() => self.number(i),
            (Some('('), _) => {
                self.enter(i)?;
                *i = &i[1..];
                let mut v = self.sum(i)?;
                self.expect(i, ")")?;
                self.depth -= 1;
                v.at = at;
                Ok(v)
            }
            (Some('['), _) => {
                self.enter(i)?;
                *i = &i[1..];
                let x = self.sum(i)?;
                self.expect(i, ",")?;
                let y = self.sum(i)?;
                self.expect(i, "]")?;
                self.depth -= 1;
                self.b.expect(&x, Type::Scalar, "a vector's component")?;
                self.b.expect(&y, Type::Scalar, "a vector's component")?;
                Ok(Val {
                    ty: Type::Vector,
                    regs: [x.regs[0], y.regs[0]],
                    at,
                })
            }
            (Some(c), _) if is_name_start(c) => self.named(i),
            _ => Err(self.syntax(i, "an operand (a number, a name, `(` or `[`)")),
        }
    }

    fn number(&mut self, i: &mut &str) -> Result<Val> {
        let at = self.at(i);
        let value: f64 = float::<_, f64, ContextError>
            .parse_next(i)
            .map_err(|_| self.syntax(i, "a number"))?;
        let r = self.b.constant(value, at)?;
        Ok(Builder::scalar(r, at))
    }

    /// A name: a call, a constant, a name of the scope, or a member of one of its objects.
    fn named(&mut self, i: &mut &str) -> Result<Val> {
        let at = self.at(i);
        let name = self.name(i)?;
        let mut primes = 0;
        while let Some(rest) = i.strip_prefix('\'') {
            *i = rest;
            primes += 1;
        }
        let mut look = *i;
        ws(&mut look);
        if look.starts_with('(') {
            *i = look;
            return self.call(i, name, primes, at);
        }
        if primes > 0 {
            return Err(self.syntax(i, &format!("`(` after `{name}{}`", "'".repeat(primes))));
        }
        if builtin(name).is_some() {
            return Err(self.syntax(i, &format!("`(` after the function `{name}`")));
        }
        if let Some((_, c)) = CONSTANTS.iter().find(|(n, _)| *n == name) {
            let r = self.b.constant(*c, at)?;
            return Ok(Builder::scalar(r, at));
        }
        let scope_err = |b: &Builder, at: usize, message: String| Error::Scope {
            column: b.col(at),
            message,
        };
        // `K.radius`: a member of an object of the scope (a vector's `.x` is read later).
        if let Some(rest) = look.strip_prefix('.') {
            let mut r = rest;
            ws(&mut r);
            if r.starts_with(is_name_start) {
                let member_at = self.at(r);
                let member = self.name(&mut r)?;
                match self.scope.member(name, member) {
                    Ok(Some(v)) => {
                        *i = r;
                        return self.b.value(&v, &[], at);
                    }
                    Ok(None) => {}
                    Err(m) => return Err(scope_err(self.b, member_at, m)),
                }
            }
        }
        match self.scope.value(name) {
            Ok(Some(v)) => return self.b.value(&v, &[], at),
            Ok(None) => {}
            Err(m) => return Err(scope_err(self.b, at, m)),
        }
        Err(Error::UnknownName {
            column: self.b.col(at),
            name: name.to_owned(),
        })
    }

    fn call(&mut self, i: &mut &str, name: &str, primes: usize, at: usize) -> Result<Val> {
        self.enter(i)?;
        *i = &i[1..];
        let mut args = Vec::new();
        if !Self::eat(i, ")") {
            loop {
                args.push(self.sum(i)?);
                if Self::eat(i, ",") {
                    continue;
                }
                self.expect(i, ")")?;
                break;
            }
        }
        self.depth -= 1;
        if primes == 0 {
            if let Some((f, types, _)) = builtin(name) {
                return self.builtin(f, name, types, &args, at);
            }
        }
        let call_args: Vec<CallArg> = args
            .iter()
            .map(|a| match (a.ty, self.b.const_of(a.regs[0])) {
                (Type::Vector, _) => CallArg::Vector,
                (Type::Scalar, Some(c)) => CallArg::Const(c),
                (Type::Scalar, None) => CallArg::Varying(self.b.identity(a.regs[0])),
            })
            .collect();
        let varying: Vec<Reg> = args
            .iter()
            .filter(|a| a.ty == Type::Scalar && self.b.const_of(a.regs[0]).is_none())
            .map(|a| a.regs[0])
            .collect();
        match self.scope.call(name, primes, &call_args) {
            Ok(Some(v)) => self.b.value(&v, &varying, at),
            Ok(None) => Err(Error::UnknownName {
                column: self.b.col(at),
                name: format!("{name}{}", "'".repeat(primes)),
            }),
            Err(message) => Err(Error::Scope {
                column: self.b.col(at),
                message,
            }),
        }
    }

    fn builtin(
        &mut self,
        f: Builtin,
        name: &str,
        types: &[Type],
        args: &[Val],
        at: usize,
    ) -> Result<Val> {
        if args.len() != types.len() {
            return Err(Error::Arity {
                column: self.b.col(at),
                function: name.to_owned(),
                expected: types.len(),
                found: args.len(),
            });
        }
        let what = format!("`{name}`");
        for (a, t) in args.iter().zip(types) {
            self.b.expect(a, *t, &what)?;
        }
        let b = &mut *self.b;
        let s = |r: Reg| Builder::scalar(r, at);
        Ok(match f {
            Builtin::Scalar(fun) => s(b.fun(fun, args[0].regs[0], at)?),
            Builtin::Atan2 => s(b.bin(Bin::Atan2, args[0].regs[0], args[1].regs[0], at, at)?),
            Builtin::Hypot => {
                let (x, y) = (args[0].regs[0], args[1].regs[0]);
                let xx = b.bin(Bin::Mul, x, x, at, at)?;
                let yy = b.bin(Bin::Mul, y, y, at, at)?;
                let sum = b.bin(Bin::Add, xx, yy, at, at)?;
                s(b.fun(Fun::Sqrt, sum, at)?)
            }
            Builtin::Dot => s(dot(b, args[0].regs, args[1].regs, at)?),
            Builtin::Cross => s(cross(b, args[0].regs, args[1].regs, at)?),
            Builtin::Norm => {
                let d = dot(b, args[0].regs, args[0].regs, at)?;
                s(b.fun(Fun::Sqrt, d, at)?)
            }
            Builtin::Unit => {
                let v = args[0].regs;
                let d = dot(b, v, v, at)?;
                let n = b.fun(Fun::Sqrt, d, at)?;
                Val {
                    ty: Type::Vector,
                    regs: [
                        b.bin(Bin::Div, v[0], n, at, at)?,
                        b.bin(Bin::Div, v[1], n, at, at)?,
                    ],
                    at,
                }
            }
            Builtin::Perp => {
                let v = args[0].regs;
                Val {
                    ty: Type::Vector,
                    regs: [b.fun(Fun::Neg, v[1], at)?, v[0]],
                    at,
                }
            }
            Builtin::Angle => {
                let (u, v) = (args[0].regs, args[1].regs);
                let c = cross(b, u, v, at)?;
                let d = dot(b, u, v, at)?;
                s(b.bin(Bin::Atan2, c, d, at, at)?)
            }
            Builtin::Vec => Val {
                ty: Type::Vector,
                regs: [args[0].regs[0], args[1].regs[0]],
                at,
            },
        })
    }

    /// a + b or a − b (both scalars or both vectors).
    fn arith(&mut self, op: Bin, a: Val, b: Val, what: &str) -> Result<Val> {
        self.b.expect(&b, a.ty, what)?;
        let x = self.b.bin(op, a.regs[0], b.regs[0], a.at, b.at)?;
        let y = match a.ty {
            Type::Scalar => x,
            Type::Vector => self.b.bin(op, a.regs[1], b.regs[1], a.at, b.at)?,
        };
        Ok(Val {
            ty: a.ty,
            regs: [x, y],
            at: a.at,
        })
    }

    fn mul(&mut self, a: Val, b: Val) -> Result<Val> {
        let (s, v, ty) = match (a.ty, b.ty) {
            (Type::Scalar, Type::Scalar) => {
                let r = self.b.bin(Bin::Mul, a.regs[0], b.regs[0], a.at, b.at)?;
                return Ok(Builder::scalar(r, a.at));
            }
            (Type::Scalar, Type::Vector) => (a, b, Type::Vector),
            (Type::Vector, Type::Scalar) => (b, a, Type::Vector),
            (Type::Vector, Type::Vector) => {
                return Err(Error::Type {
                    column: self.b.col(b.at),
                    what: "`*` of a vector (use dot(a, b) or cross(a, b))".into(),
                    expected: crate::errors::TypeWord(Type::Scalar),
                    found: crate::errors::TypeWord(Type::Vector),
                })
            }
        };
        Ok(Val {
            ty,
            regs: [
                self.b.bin(Bin::Mul, s.regs[0], v.regs[0], a.at, b.at)?,
                self.b.bin(Bin::Mul, s.regs[0], v.regs[1], a.at, b.at)?,
            ],
            at: a.at,
        })
    }

    fn div(&mut self, a: Val, b: Val) -> Result<Val> {
        self.b.expect(&b, Type::Scalar, "`/`")?;
        let x = self.b.bin(Bin::Div, a.regs[0], b.regs[0], a.at, b.at)?;
        let y = match a.ty {
            Type::Scalar => x,
            Type::Vector => self.b.bin(Bin::Div, a.regs[1], b.regs[0], a.at, b.at)?,
        };
        Ok(Val {
            ty: a.ty,
            regs: [x, y],
            at: a.at,
        })
    }

    fn neg(&mut self, v: Val) -> Result<Val> {
        let x = self.b.fun(Fun::Neg, v.regs[0], v.at)?;
        let y = match v.ty {
            Type::Scalar => x,
            Type::Vector => self.b.fun(Fun::Neg, v.regs[1], v.at)?,
        };
        Ok(Val {
            ty: v.ty,
            regs: [x, y],
            at: v.at,
        })
    }

    /// aᵉ: an integer constant exponent as repeated products (exact for negative a), any
    /// other as exp(e·ln a).
    fn pow(&mut self, a: Val, e: Val) -> Result<Val> {
        self.b.expect(&a, Type::Scalar, "`^`")?;
        self.b.expect(&e, Type::Scalar, "`^`")?;
        let r = match self.b.const_of(e.regs[0]) {
            Some(n) if n.fract() == 0.0 && n.abs() <= 1024.0 => {
                // |n| ≤ 1024, so the conversion is exact.
                #[allow(clippy::cast_possible_truncation)] // checked just above
                let n = n as i32;
                if n < 0 && self.b.const_of(a.regs[0]) == Some(0.0) {
                    return Err(Error::DivisionByZero {
                        column: self.b.col(a.at),
                    });
                }
                self.b.powi(a.regs[0], n, a.at)?
            }
            _ => self.b.bin(Bin::Pow, a.regs[0], e.regs[0], a.at, e.at)?,
        };
        Ok(Builder::scalar(r, a.at))
    }
}

fn dot(b: &mut Builder, u: [Reg; 2], v: [Reg; 2], at: usize) -> Result<Reg> {
    let xx = b.bin(Bin::Mul, u[0], v[0], at, at)?;
    let yy = b.bin(Bin::Mul, u[1], v[1], at, at)?;
    b.bin(Bin::Add, xx, yy, at, at)
}

fn cross(b: &mut Builder, u: [Reg; 2], v: [Reg; 2], at: usize) -> Result<Reg> {
    let xy = b.bin(Bin::Mul, u[0], v[1], at, at)?;
    let yx = b.bin(Bin::Mul, u[1], v[0], at, at)?;
    b.bin(Bin::Sub, xy, yx, at, at)
}
