//! `Sketch.add_expression`: the file form of an expression constraint from Python values
//! (rows as a string or a list, arguments as entity ids or file forms).

use camber_sketch::{EntityId, Sketch};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use serde_json::{json, Map, Value};

use crate::errors;
use crate::json::to_value;

/// An argument: an int is an entity, named by its kind; anything else is its file form.
fn arg(sketch: &Sketch, name: &str, v: &Bound<'_, PyAny>) -> PyResult<Value> {
    if let Ok(id) = v.extract::<u64>() {
        let e = sketch.entity(EntityId(id)).map_err(errors::sketch)?;
        let key = match e.kind_name() {
            "point" => "point",
            "circle" => "circle",
            "line" => "line",
            _ => "curve",
        };
        return Ok(json!({ key: id }));
    }
    let form = to_value(v)?;
    if form.is_object() {
        Ok(form)
    } else {
        Err(errors::SketchError::new_err(format!(
            "the argument `{name}` is an entity id or a form such as {{\"free\": 0.5}}, found {form}"
        )))
    }
}

/// The file form `{"kind": "expression", "name", "rows", "args"}`.
pub fn form(
    sketch: &Sketch,
    rows: &Bound<'_, PyAny>,
    name: String,
    args: Option<&Bound<'_, PyDict>>,
) -> PyResult<Value> {
    let rows: Vec<String> = match rows.extract::<String>() {
        Ok(one) => vec![one],
        Err(_) => rows
            .extract::<Vec<String>>()
            .map_err(|_| errors::SketchError::new_err("rows is a string or a list of strings"))?,
    };
    let mut map = Map::new();
    if let Some(args) = args {
        for (k, v) in args.iter() {
            let key: String = k.extract()?;
            map.insert(key.clone(), arg(sketch, &key, &v)?);
        }
    }
    Ok(json!({"kind": "expression", "name": name, "rows": rows, "args": map}))
}
