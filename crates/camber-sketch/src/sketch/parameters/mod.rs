//! Named parameters of a sketch, and dimensions written as expressions of them.
//!
//! A sketch holds parameters (`chord = 1.0`, `t_max = 0.12`). Expression constraints read them
//! by name; any number of a constraint's file form (a distance, a radius, an angle, an arc
//! length, a coordinate of a target) may instead be an expression of them, written where the
//! number goes: `{"kind": "distance", …, "distance": "chord / 2"}`. The sketch keeps each such
//! *binding* (the field's JSON path and its text), gives the constraint the value, and writes
//! the text back when saving. [`crate::Sketch::set_parameter`] re-evaluates the bindings and
//! expressions that read the parameter and re-solves only their components.
//!
//! A dimension's text is compiled by [`camber_expr`] over the parameters alone, so it must be
//! a constant scalar: `chord / 2`, `t_max * chord`, `atan2(1, 3)`.

use std::collections::{BTreeMap, BTreeSet};

use serde_json::Value;

use crate::constraints::Constraint;
use crate::ground::errors::{Error, Result};

mod ordered;

/// One named parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Parameter {
    /// The value.
    pub value: f64,
}

/// A dimension written as an expression: the JSON path of the number in the constraint's file
/// form (`distance`, `target.at[0]`) and the text.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Binding {
    /// The path of the number (serde's form: fields joined by `.`, indices in brackets).
    pub path: String,
    /// The expression.
    pub text: String,
}

/// The parameters of a sketch and the bindings of its dimensions.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Parameters {
    pub(crate) values: BTreeMap<String, Parameter>,
    pub(crate) bindings: BTreeMap<crate::ground::ids::ConstraintId, Vec<Binding>>,
}

/// A scope of the parameters as constants, recording which it reads.
struct Constants<'a> {
    values: &'a BTreeMap<String, Parameter>,
    read: BTreeSet<String>,
}

impl camber_expr::Scope for Constants<'_> {
    fn value(&mut self, name: &str) -> std::result::Result<Option<camber_expr::Value>, String> {
        let Some(p) = self.values.get(name) else {
            return Ok(None);
        };
        self.read.insert(name.to_owned());
        Ok(Some(camber_expr::Value::Scalar(camber_expr::Term::Const(
            p.value,
        ))))
    }
}

impl Parameters {
    /// The parameter `name`.
    pub fn get(&self, name: &str) -> Option<Parameter> {
        self.values.get(name).copied()
    }

    /// Every parameter, by name.
    pub fn iter(&self) -> impl Iterator<Item = (&str, Parameter)> {
        self.values.iter().map(|(n, p)| (n.as_str(), *p))
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.values.is_empty()
    }

    /// The bindings of a constraint's dimensions.
    pub fn bindings(&self, id: crate::ground::ids::ConstraintId) -> &[Binding] {
        self.bindings.get(&id).map_or(&[], Vec::as_slice)
    }

    /// The value of a dimension's text over the parameters, and the parameters it reads.
    ///
    /// ```
    /// use camber_sketch::Sketch;
    /// let mut s = Sketch::new();
    /// s.define_parameter("chord", 2.0)?;
    /// let (v, read) = s.parameters().evaluate("chord / 4 + 1")?;
    /// assert!((v - 1.5).abs() < 1e-15 && read.contains("chord"));
    /// assert!(s.parameters().evaluate("span").is_err());
    /// # Ok::<(), camber_sketch::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::Expression`]: the language's errors, an unknown parameter, a vector.
    pub fn evaluate(&self, text: &str) -> Result<(f64, BTreeSet<String>)> {
        let mut scope = Constants {
            values: &self.values,
            read: BTreeSet::new(),
        };
        let program = camber_expr::compile(&[text], &mut scope)?;
        if program.rows() != 1 {
            return Err(Error::Expression(camber_expr::Error::Type {
                column: 1,
                what: "a dimension".into(),
                expected: camber_expr::errors::TypeWord(camber_expr::Type::Scalar),
                found: camber_expr::errors::TypeWord(camber_expr::Type::Vector),
            }));
        }
        let mut out = [f64::NAN];
        program.eval::<f64, ()>(&[], &(), &mut out);
        if !out[0].is_finite() {
            return Err(Error::Expression(camber_expr::Error::NonFinite {
                column: 1,
                value: out[0],
            }));
        }
        Ok((out[0], scope.read))
    }

    /// Whether the text of any binding of `id` reads `name`.
    pub(crate) fn binding_reads(&self, id: crate::ground::ids::ConstraintId, name: &str) -> bool {
        self.bindings(id).iter().any(|b| mentions(&b.text, name))
    }
}

/// Whether `text` mentions the name `name` (as a whole word of name characters).
pub(crate) fn mentions(text: &str, name: &str) -> bool {
    text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .any(|w| w == name)
}

/// The steps of a serde path (`target.at[0]` → key target, key at, index 0).
fn steps(path: &str) -> Vec<Step<'_>> {
    let mut out = Vec::new();
    for part in path.split('.') {
        let (key, rest) = part.split_once('[').map_or((part, ""), |(k, r)| (k, r));
        if !key.is_empty() {
            out.push(Step::Key(key));
        }
        for index in rest.split('[') {
            if let Some(n) = index.strip_suffix(']').and_then(|n| n.parse().ok()) {
                out.push(Step::Index(n));
            }
        }
    }
    out
}

enum Step<'a> {
    Key(&'a str),
    Index(usize),
}

/// The value at `path`, mutably.
pub(crate) fn at_path<'v>(value: &'v mut Value, path: &str) -> Option<&'v mut Value> {
    let mut v = value;
    for s in steps(path) {
        v = match s {
            Step::Key(k) => v.as_object_mut()?.get_mut(k)?,
            Step::Index(i) => v.as_array_mut()?.get_mut(i)?,
        };
    }
    Some(v)
}

/// Why a form was refused: the JSON path and the message.
pub(crate) type Refusal = (String, String);

/// The most strings one constraint's form may hold as dimensions.
const MAX_BINDINGS: usize = 64;

/// Reads a constraint's file form whose numbers may be expressions of `parameters`: each
/// string where the kind expects a number is evaluated and recorded as a binding.
///
/// Returns `None` for an unknown kind; `Some(Err((path, message)))` for a shape error or an
/// expression the language refuses (its path, and the message with the column).
pub(crate) fn load_with_dimensions(
    tag: &str,
    mut value: Value,
    parameters: &Parameters,
) -> Option<std::result::Result<(Constraint, Vec<Binding>), Refusal>> {
    let mut bindings = Vec::new();
    loop {
        match Constraint::load(tag, value.clone())? {
            Ok(c) => return Some(Ok((c, bindings))),
            Err(e) => {
                let number_expected =
                    e.message.starts_with("invalid type: string") && bindings.len() < MAX_BINDINGS;
                let text = match at_path(&mut value, &e.path) {
                    Some(Value::String(t)) if number_expected => t.clone(),
                    _ => return Some(Err((e.path, e.message))),
                };
                let v = match parameters.evaluate(&text) {
                    Ok((v, _)) => v,
                    Err(err) => return Some(Err((e.path, err.to_string()))),
                };
                if let Some(slot) = at_path(&mut value, &e.path) {
                    *slot = Value::from(v);
                }
                bindings.push(Binding { path: e.path, text });
            }
        }
    }
}

/// The constraint with each binding's number set to its text's value over `parameters`.
///
/// # Errors
/// [`Error::Expression`] for a text that no longer evaluates; [`Error::Expression`] (a
/// scope error) when the form no longer reads back.
pub(crate) fn apply(
    constraint: &Constraint,
    bindings: &[Binding],
    parameters: &Parameters,
) -> Result<Constraint> {
    let shape =
        |message: String| Error::Expression(camber_expr::Error::Scope { column: 1, message });
    let text = constraint.save().map_err(|e| shape(e.to_string()))?;
    let mut value: Value = serde_json::from_str(&text).map_err(|e| shape(e.to_string()))?;
    for b in bindings {
        let (v, _) = parameters.evaluate(&b.text)?;
        match at_path(&mut value, &b.path) {
            Some(slot) => *slot = Value::from(v),
            None => {
                return Err(shape(format!(
                    "the dimension `{}` is no longer there",
                    b.path
                )))
            }
        }
    }
    match Constraint::load(constraint.tag(), value) {
        Some(Ok(c)) => Ok(c),
        Some(Err(e)) => Err(shape(format!("at {}: {}", e.path, e.message))),
        None => Err(shape(format!("unknown kind {}", constraint.tag()))),
    }
}

/// A constraint's file form with each binding's text in place of its number (the kind's
/// field order kept).
pub(crate) fn with_texts(body: &str, bindings: &[Binding]) -> serde_json::Result<String> {
    let mut value: ordered::Ordered = serde_json::from_str(body)?;
    for b in bindings {
        let mut v = Some(&mut value);
        for s in steps(&b.path) {
            v = v.and_then(|x| x.child(&s));
        }
        if let Some(slot) = v {
            *slot = ordered::Ordered::Leaf(Value::String(b.text.clone()));
        }
    }
    serde_json::to_string(&value)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn serde_paths_split_into_keys_and_indices() {
        let mut v = serde_json::json!({"target": {"at": [1.0, 2.0]}, "distance": 3.0});
        assert_eq!(at_path(&mut v, "target.at[1]"), Some(&mut Value::from(2.0)));
        assert_eq!(at_path(&mut v, "distance"), Some(&mut Value::from(3.0)));
        assert_eq!(at_path(&mut v, "target.at[2]"), None);
        assert!(mentions("2 * chord + t_max", "chord") && !mentions("chords", "chord"));
    }
}
