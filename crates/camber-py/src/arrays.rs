//! Conversions between numpy arrays and camber's points, vectors and parameter lists.
//!
//! Points travel as `(n, d)` float arrays (d = 2 or 3), parameters as a float or a 1-D array;
//! anything numpy can turn into floats (lists, integer arrays) is accepted.

use nalgebra::{Point, SVector};
use numpy::ndarray::Array2;
use numpy::{AllowTypeChange, IntoPyArray, PyArray2, PyArrayLike1, PyArrayLike2};
use pyo3::prelude::*;
use pyo3::types::{PyFloat, PyInt};

use crate::errors::input;

/// Parameters given as one float or as a 1-D array of floats.
pub enum Params {
    /// One parameter: results drop the leading axis.
    One(f64),
    /// Many parameters.
    Many(Vec<f64>),
}

impl Params {
    /// Reads a float or anything numpy converts to a 1-D float array, in any memory layout
    /// (a strided or reversed view such as `u[::2]` or `u[::-1]` is read element by element).
    pub fn extract(u: &Bound<'_, PyAny>) -> PyResult<Self> {
        // Python floats and ints first: no numpy round trip for one plain number.
        if u.is_instance_of::<PyFloat>() || u.is_instance_of::<PyInt>() {
            return Ok(Params::One(u.extract::<f64>()?));
        }
        refuse_complex(u, "parameters")?;
        if let Ok(x) = u.extract::<f64>() {
            return Ok(Params::One(x));
        }
        let a: PyArrayLike1<'_, f64, AllowTypeChange> = u.extract()?;
        Ok(Params::Many(a.as_array().to_vec()))
    }

    /// The parameters as a slice.
    pub fn as_slice(&self) -> &[f64] {
        match self {
            Params::One(x) => std::slice::from_ref(x),
            Params::Many(v) => v,
        }
    }
}

/// Refuses complex numbers (an array of complex dtype, or a sequence numpy reads as one):
/// converted to floats they would lose their imaginary parts without a word.
pub fn refuse_complex(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<()> {
    let numpy = obj.py().import("numpy")?;
    let kind: String = numpy
        .getattr("asarray")?
        .call1((obj,))
        .and_then(|a| a.getattr("dtype")?.getattr("kind")?.extract())
        .unwrap_or_default();
    if kind == "c" {
        return Err(input(format!(
            "{what}: complex numbers are not parameters or coordinates (take .real if that is \
             what you mean)"
        )));
    }
    Ok(())
}

/// A 2-D float array argument (a numpy array of any real dtype, or nested sequences numpy
/// reads as one), with complex numbers refused ([`refuse_complex`]) where numpy would drop
/// their imaginary parts with only a warning. Dereferences to the float array.
pub struct RealArray2<'py>(PyArrayLike2<'py, f64, AllowTypeChange>);

impl<'a, 'py> FromPyObject<'a, 'py> for RealArray2<'py> {
    type Error = PyErr;

    fn extract(ob: Borrowed<'a, 'py, PyAny>) -> PyResult<Self> {
        refuse_complex(&ob, "coordinates")?;
        Ok(Self(ob.extract()?))
    }
}

impl<'py> std::ops::Deref for RealArray2<'py> {
    type Target = PyArrayLike2<'py, f64, AllowTypeChange>;

    fn deref(&self) -> &Self::Target {
        &self.0
    }
}

/// The column count of a 2-D array of points.
pub fn columns(a: &PyArrayLike2<'_, f64, AllowTypeChange>) -> usize {
    a.as_array().ncols()
}

/// Rows of a `(n, D)` array as points.
pub fn points<const D: usize>(
    a: &PyArrayLike2<'_, f64, AllowTypeChange>,
    what: &str,
) -> PyResult<Vec<Point<f64, D>>> {
    let view = a.as_array();
    if view.ncols() != D {
        return Err(input(format!(
            "{what}: expected an (n, {D}) array, found shape {:?}",
            view.shape()
        )));
    }
    Ok(view
        .rows()
        .into_iter()
        .map(|r| Point::from(SVector::<f64, D>::from_fn(|i, _| r[i])))
        .collect())
}

/// A point or vector of dimension D from a sequence of D floats.
pub fn vector<const D: usize>(v: &[f64], what: &str) -> PyResult<SVector<f64, D>> {
    if v.len() != D {
        return Err(input(format!(
            "{what}: expected {D} coordinates, found {}",
            v.len()
        )));
    }
    Ok(SVector::<f64, D>::from_fn(|i, _| v[i]))
}

/// Points as an `(n, D)` array.
pub fn points_array<'py, const D: usize>(
    py: Python<'py>,
    points: &[Point<f64, D>],
) -> Bound<'py, PyArray2<f64>> {
    let flat: Vec<f64> = points
        .iter()
        .flat_map(|p| p.coords.iter().copied())
        .collect();
    rows_array(py, flat, D)
}

/// A flat row-major buffer as an `(len / width, width)` array.
pub fn rows_array(py: Python<'_>, flat: Vec<f64>, width: usize) -> Bound<'_, PyArray2<f64>> {
    let n = flat.len() / width.max(1);
    // The buffer holds exactly n · width values by construction, so the shape always fits.
    Array2::from_shape_vec((n, width), flat)
        .unwrap_or_else(|_| Array2::zeros((0, width)))
        .into_pyarray(py)
}
