//! Sweeps: one sketch solved for every row of a table of parameter values, on a rayon pool,
//! one row of results per variant (what `camber batch --parameters` and Python's
//! `solve_many(sketch, parameters=…)` run).

use rayon::prelude::*;

use crate::constraints::Constraint;
use crate::ground::errors::{Error, Result};
use crate::sketch::Sketch;

/// Parameter values by column: `names[k]` takes `columns[k][i]` in variant i.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    names: Vec<String>,
    columns: Vec<Vec<f64>>,
}

impl Table {
    /// A table of equally long columns.
    ///
    /// # Errors
    /// [`Error::CountMismatch`] for columns of different lengths (naming the first that
    /// differs); [`Error::NonFinite`] for a NaN or infinite value.
    pub fn try_new(columns: Vec<(String, Vec<f64>)>) -> Result<Self> {
        let rows = columns.first().map_or(0, |(_, c)| c.len());
        for (_, c) in &columns {
            if c.len() != rows {
                return Err(Error::CountMismatch {
                    field: "parameter table column",
                    expected: rows,
                    found: c.len(),
                });
            }
            if let Some((i, v)) = c.iter().enumerate().find(|(_, v)| !v.is_finite()) {
                return Err(Error::NonFinite {
                    what: "parameter value in row",
                    index: i,
                    value: *v,
                });
            }
        }
        let (names, columns) = columns.into_iter().unzip();
        Ok(Self { names, columns })
    }

    /// The number of variants (rows).
    pub fn rows(&self) -> usize {
        self.columns.first().map_or(0, Vec::len)
    }

    /// The parameter names (columns).
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// Variant `i`: (name, value) pairs.
    pub fn row(&self, i: usize) -> impl Iterator<Item = (&str, f64)> + '_ {
        self.names
            .iter()
            .zip(&self.columns)
            .filter_map(move |(n, c)| c.get(i).map(|v| (n.as_str(), *v)))
    }
}

/// The result of one variant.
#[derive(Debug, Clone, PartialEq)]
pub struct VariantResult {
    /// Its row in the table.
    pub row: usize,
    /// Whether it solved.
    pub ok: bool,
    /// The largest |residual| after the solve (NaN when it failed).
    pub max_residual: f64,
    /// The solved free parameters of the constraints, by constraint id: (constraint id, name,
    /// value), the name an expression's argument (`s` of `{"s": {"free": 0.4}}`) or the field
    /// of a built-in kind that holds `{"free": u}` (`u` of a `tangent_to_circle`).
    pub free: Vec<(u64, String, f64)>,
    /// Why it failed.
    pub error: Option<String>,
}

/// Solves `base` for every row of `table` on `threads` workers (all cores when `None`): each
/// variant is a copy of `base` with the row's parameters set ([`Sketch::define_parameter`]),
/// re-solved where they are read. One failure stays on its row.
///
/// ```
/// use camber_sketch::constraints::Distance;
/// use camber_sketch::parameters::sweep::{solve_variants, Table};
/// use camber_sketch::{PointRef, Sketch};
/// use nalgebra::Point2;
/// let mut s = Sketch::new();
/// let (a, b) = (s.add_point(Point2::new(0.0, 0.0))?, s.add_point(Point2::new(1.0, 0.0))?);
/// s.define_parameter("gap", 1.0)?;
/// let d = s.add_constraint(Distance { a: PointRef::Point(a), b: PointRef::Point(b), distance: 1.0 })?;
/// s.bind_dimension(d, "distance", "gap")?;
/// let table = Table::try_new(vec![("gap".into(), vec![0.5, 2.0, -1.0])])?;
/// let rows = solve_variants(&s, &table, Some(2))?;
/// assert!(rows[0].ok && rows[1].ok && !rows[2].ok); // a negative distance is refused
/// # Ok::<(), camber_sketch::Error>(())
/// ```
///
/// # Errors
/// [`Error::InvalidOption`] when the pool cannot start; a column naming no parameter of the
/// sketch ([`Error::Expression`]).
pub fn solve_variants(
    base: &Sketch,
    table: &Table,
    threads: Option<usize>,
) -> Result<Vec<VariantResult>> {
    for n in table.names() {
        if base.parameter(n).is_none() {
            return Err(Error::Expression(camber_expr::Error::Scope {
                column: 1,
                message: format!("the table's column `{n}` names no parameter of the sketch"),
            }));
        }
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads.unwrap_or(0))
        .build()
        .map_err(|e| Error::InvalidOption {
            what: "threads",
            detail: e.to_string(),
        })?;
    Ok(pool.install(|| {
        (0..table.rows())
            .into_par_iter()
            .map(|i| variant(base, table, i))
            .collect()
    }))
}

/// The free parameters of one constraint with their values: an expression's `{"free": v}`
/// arguments by name; for the other kinds, the fields of the file form that hold
/// `{"free": u}` (contact parameters), by field name.
fn free_parameters(c: &Constraint) -> Vec<(String, f64)> {
    if let Constraint::Expression(e) = c {
        return e
            .free_parameters()
            .into_iter()
            .map(|(n, v)| (n.to_owned(), v))
            .collect();
    }
    let Ok(serde_json::Value::Object(fields)) = c
        .save()
        .and_then(|text| serde_json::from_str::<serde_json::Value>(&text))
    else {
        return Vec::new();
    };
    fields
        .into_iter()
        .filter_map(|(name, value)| {
            let value = value.as_object()?;
            match (
                value.len(),
                value.get("free").and_then(serde_json::Value::as_f64),
            ) {
                (1, Some(u)) => Some((name, u)),
                _ => None,
            }
        })
        .collect()
}

fn variant(base: &Sketch, table: &Table, row: usize) -> VariantResult {
    let mut s = base.clone();
    let outcome = table
        .row(row)
        .try_for_each(|(n, v)| s.define_parameter(n, v).map(|_| ()))
        .and_then(|()| s.solve());
    match outcome {
        Ok(report) => VariantResult {
            row,
            ok: true,
            max_residual: report
                .components
                .iter()
                .flat_map(|c| c.report.residuals.iter().map(|r| r.max_abs))
                .fold(0.0, f64::max),
            free: s
                .constraints()
                .flat_map(|(id, c)| {
                    free_parameters(c)
                        .into_iter()
                        .map(move |(n, v)| (id.0, n, v))
                })
                .collect(),
            error: None,
        },
        Err(e) => VariantResult {
            row,
            ok: false,
            max_residual: f64::NAN,
            free: Vec::new(),
            error: Some(e.to_string()),
        },
    }
}
