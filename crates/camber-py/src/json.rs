//! Python objects ⇄ serde_json values, through Python's own `json` module: the bindings hand
//! constraint fields and point references to the library's serde forms, and the library's
//! reports (which implement `Serialize`) come back as dicts.

use pyo3::prelude::*;
use serde::Serialize;
use serde_json::Value;

use crate::errors::input;

/// A Python object (dicts, lists, numbers, strings, numpy scalars and arrays) as a JSON value.
///
/// # Errors
/// `SketchError` naming the field of a NaN or infinite number (JSON has none, and no sketch
/// field takes one); `TypeError` for an object JSON cannot hold.
pub fn to_value(obj: &Bound<'_, PyAny>) -> PyResult<Value> {
    let py = obj.py();
    let convert = py.import("camber._convert")?;
    let found = convert.getattr("non_finite")?.call1((obj,))?;
    if !found.is_none() {
        let (path, value): (String, f64) = found.extract()?;
        return Err(crate::errors::SketchError::new_err(format!(
            "{path} is not finite ({value}): sketch fields take finite numbers"
        )));
    }
    let dumps = py.import("json")?.getattr("dumps")?;
    let kwargs = pyo3::types::PyDict::new(py);
    // numpy arrays and scalars become lists and floats.
    kwargs.set_item("default", convert.getattr("plain")?)?;
    let text: String = dumps.call((obj,), Some(&kwargs))?.extract()?;
    serde_json::from_str(&text).map_err(|e| input(format!("not a JSON value: {e}")))
}

/// Any serializable value as a Python object (dicts, lists, floats, ints, strings, None).
pub fn to_python<T: Serialize>(py: Python<'_>, value: &T) -> PyResult<Py<PyAny>> {
    let text = serde_json::to_string(value).map_err(|e| input(e.to_string()))?;
    Ok(py
        .import("json")?
        .getattr("loads")?
        .call1((text,))?
        .unbind())
}
