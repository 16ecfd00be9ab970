//! Shared pieces of the JSON form of f64 geometry: points as coordinate arrays, validated on
//! the way in.
//!
//! Each curve type serializes through a plain "raw" struct of `Vec`s and `f64`s and rebuilds
//! itself with its `try_new` on deserialize, so a file can never hold a curve the constructors
//! would reject. Points are arrays of D numbers (`[x, y]` or `[x, y, z]`).

use nalgebra::{Point, SVector};

use crate::errors::{Error, Result};

/// A point or vector as a list of coordinates.
pub type RawPoint = Vec<f64>;

/// The coordinates of a point as a list.
pub fn point_to_raw<const D: usize>(p: &Point<f64, D>) -> RawPoint {
    p.coords.iter().copied().collect()
}

/// The coordinates of a vector as a list.
pub fn vector_to_raw<const D: usize>(v: &SVector<f64, D>) -> RawPoint {
    v.iter().copied().collect()
}

/// The coordinates of many points.
pub fn points_to_raw<const D: usize>(points: &[Point<f64, D>]) -> Vec<RawPoint> {
    points.iter().map(point_to_raw).collect()
}

/// A vector from a list of exactly D coordinates; `index` names it in the error.
pub fn vector_from_raw<const D: usize>(raw: &[f64], index: usize) -> Result<SVector<f64, D>> {
    if raw.len() != D {
        return Err(Error::Dimension {
            index,
            expected: D,
            found: raw.len(),
        });
    }
    Ok(SVector::<f64, D>::from_column_slice(raw))
}

/// A point from a list of exactly D coordinates; `index` names it in the error.
pub fn point_from_raw<const D: usize>(raw: &[f64], index: usize) -> Result<Point<f64, D>> {
    vector_from_raw(raw, index).map(Point::from)
}

/// Points from lists of exactly D coordinates each.
pub fn points_from_raw<const D: usize>(raw: &[RawPoint]) -> Result<Vec<Point<f64, D>>> {
    raw.iter()
        .enumerate()
        .map(|(i, r)| point_from_raw(r, i))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrong_dimension_names_the_point() {
        let raw = vec![vec![0.0, 1.0], vec![2.0]];
        assert_eq!(
            points_from_raw::<2>(&raw),
            Err(Error::Dimension {
                index: 1,
                expected: 2,
                found: 1
            })
        );
        let ok = points_from_raw::<2>(&raw[..1]).unwrap();
        assert_eq!(points_to_raw(&ok), vec![vec![0.0, 1.0]]);
    }
}
