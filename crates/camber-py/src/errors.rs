//! The exception hierarchy of the package and the conversions of library errors into it.
//!
//! `CamberError` is the base of everything camber raises; `GeometryError` (bad curve input or
//! parameters), `SketchError` (ids, kinds, entities), its subclasses `FileError` (reading or
//! writing sketch JSON) and `SolveError` (a solve, drag or analysis that failed), and
//! `SurfaceError`. Each carries the library's own message, which names the offending entity,
//! constraint, index or value. No Rust panic crosses into Python: library code returns typed
//! errors, and the bindings convert every one of them here.

use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;

create_exception!(
    _native,
    CamberError,
    PyException,
    "Base class of every error camber raises."
);
create_exception!(
    _native,
    GeometryError,
    CamberError,
    "Bad curve input: knots, weights, control points, parameters outside the domain."
);
create_exception!(
    _native,
    SketchError,
    CamberError,
    "A sketch refused an edit: unknown ids, wrong entity kinds, invalid constraint fields."
);
create_exception!(
    _native,
    FileError,
    SketchError,
    "A sketch file could not be read or written (syntax, shape with its JSON path, ids)."
);
create_exception!(
    _native,
    SolveError,
    SketchError,
    "A solve, drag or displacement failed (conflicting or unsatisfiable constraints, crossed contacts, …)."
);
create_exception!(
    _native,
    SurfaceError,
    CamberError,
    "Bad surface input or a failed G1 deformation."
);

/// A camber-geom error as a `GeometryError`.
pub fn geometry(e: camber_geom::Error) -> PyErr {
    GeometryError::new_err(e.to_string())
}

/// A camber-sketch error as a `SketchError`.
pub fn sketch(e: camber_sketch::Error) -> PyErr {
    SketchError::new_err(e.to_string())
}

/// A camber-sketch error of a solve, drag or analysis as a `SolveError`.
pub fn solve(e: camber_sketch::Error) -> PyErr {
    SolveError::new_err(e.to_string())
}

/// A sketch file error as a `FileError`.
pub fn file(e: camber_sketch::file::FileError) -> PyErr {
    FileError::new_err(e.to_string())
}

/// A camber-surface error as a `SurfaceError`.
pub fn surface(e: camber_surface::Error) -> PyErr {
    SurfaceError::new_err(e.to_string())
}

/// Input of the wrong shape or value, detected by the bindings themselves.
pub fn input(message: impl Into<String>) -> PyErr {
    GeometryError::new_err(message.into())
}

/// Adds the exception classes to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("CamberError", py.get_type::<CamberError>())?;
    m.add("GeometryError", py.get_type::<GeometryError>())?;
    m.add("SketchError", py.get_type::<SketchError>())?;
    m.add("FileError", py.get_type::<FileError>())?;
    m.add("SolveError", py.get_type::<SolveError>())?;
    m.add("SurfaceError", py.get_type::<SurfaceError>())?;
    Ok(())
}

/// A camber-sketch error of a solve, drag or analysis of `sketch` as a `SolveError`, its
/// constraints named by id and kind as the CLI names them ("constraint 4 (distance)").
pub fn solve_in(sketch: &camber_sketch::Sketch, e: camber_sketch::Error) -> PyErr {
    SolveError::new_err(sketch.describe_error(&e))
}
