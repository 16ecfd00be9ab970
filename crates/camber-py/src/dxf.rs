//! DXF files in and out of sketches (`camber.read_dxf`, `camber.write_dxf`), through
//! camber-interop; the GIL is released while a file is parsed, built or written.

use std::path::PathBuf;

use camber_interop::dxf::{self, Form, ReadOptions};
use pyo3::prelude::*;

use crate::errors;
use crate::sketch::Sketch;

/// Reads a DXF file (text or binary) into a sketch: lines, circles, arcs, ellipses, polylines
/// (bulges as arcs) and splines, layers as tags, end points within `join_tolerance` joined by
/// coincident constraints. Returns `(sketch, skipped)`, `skipped` a list of
/// `(location, reason)` pairs for every item left out. Raises `FileError` for a file that
/// cannot be read or is not DXF.
#[pyfunction]
#[pyo3(signature = (path, join_tolerance = 1e-9))]
pub fn read_dxf(
    py: Python<'_>,
    path: PathBuf,
    join_tolerance: f64,
) -> PyResult<(Sketch, Vec<(String, String)>)> {
    let cannot = |e: std::io::Error| {
        errors::FileError::new_err(format!("cannot read {}: {e}", path.display()))
    };
    let options = ReadOptions {
        join_tolerance,
        ..ReadOptions::default()
    };
    // The size is checked before the file is read into memory.
    let size = std::fs::metadata(&path).map_err(cannot)?.len();
    if size > options.max_bytes as u64 {
        return Err(errors::FileError::new_err(format!(
            "{}: {}",
            path.display(),
            dxf::Error::TooLarge {
                size: usize::try_from(size).unwrap_or(usize::MAX),
                limit: options.max_bytes,
            }
        )));
    }
    let bytes = std::fs::read(&path).map_err(cannot)?;
    // Ctrl-C is honoured once the parse (bounded by the size limit) returns.
    let imported = crate::interrupt::run(py, |_| dxf::read(&bytes, &options))?
        .map_err(|e| errors::FileError::new_err(format!("{}: {e}", path.display())))?;
    let skipped = imported
        .skipped
        .into_iter()
        .map(|s| (s.location, s.reason))
        .collect();
    Ok((
        Sketch {
            inner: imported.sketch,
        },
        skipped,
    ))
}

/// Writes a sketch's geometry as a DXF file (AutoCAD 2000): text, or binary
/// (the exact f64 bits) with `binary=True`; tags become layers. Raises `FileError` for a
/// tag that is not a layer name, a spline beyond DXF's counts, or a file that cannot be
/// written.
#[pyfunction]
#[pyo3(signature = (sketch, path, binary = false))]
pub fn write_dxf(py: Python<'_>, sketch: &Sketch, path: PathBuf, binary: bool) -> PyResult<()> {
    let form = if binary { Form::Binary } else { Form::Text };
    let bytes = py
        .detach(|| dxf::write(&sketch.inner, form))
        .map_err(|e| errors::FileError::new_err(e.to_string()))?;
    std::fs::write(&path, bytes)
        .map_err(|e| errors::FileError::new_err(format!("cannot write {}: {e}", path.display())))
}
