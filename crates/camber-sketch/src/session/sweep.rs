//! Sweeps: one sketch solved for every row of a table of parameter values, on a rayon pool,
//! one row of results per variant (what `camber batch --parameters` and Python's
//! `solve_many(sketch, parameters=…)` run).

use rayon::prelude::*;

use crate::constraints::Constraint;
use crate::ground::errors::{Error, Result};
use crate::session::batch::Worker;
use crate::session::solve::SketchReport;
use crate::sketch::prepared::Swept;
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
/// The rows are split into one contiguous run per worker; a worker solves each variant's
/// components on the prepared problems of its previous variant when only the swept
/// parameters differ (their readers' residuals replaced in place, the values refreshed from
/// `base`), so a component is compiled once per worker, not once per row. Each variant is
/// still solved from `base`'s values: its answer is that of solving it alone.
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
    let swept = swept_by(base, table);
    Ok(pool.install(|| {
        // One contiguous run of rows per thread, each run on one worker keeping the prepared
        // problems of its last variant.
        let rows: Vec<usize> = (0..table.rows()).collect();
        let run = rows.len().div_ceil(rayon::current_num_threads()).max(1);
        let runs: Vec<Vec<VariantResult>> = rows
            .par_chunks(run)
            .map(|chunk| {
                let mut worker = Worker::for_sweep(swept.clone());
                chunk
                    .iter()
                    .map(|&i| result_of(i, &solve_row(&mut worker, base, table, i)))
                    .collect()
            })
            .collect();
        runs.into_iter().flatten().collect()
    }))
}

/// What the variants of `table` may change against each other: its parameters and every
/// constraint of `base` that reads one of them.
fn swept_by(base: &Sketch, table: &Table) -> Swept {
    Swept {
        parameters: table.names().iter().cloned().collect(),
        readers: table
            .names()
            .iter()
            .flat_map(|n| base.parameter_readers(n))
            .collect(),
    }
}

/// Variant `row` of `base`, solved by `worker` (on the problems it kept from its last
/// variant where the structure matches; the answer is that of [`Sketch::solve`] on a copy of
/// `base` with the row's parameters set).
fn solve_row(
    worker: &mut Worker,
    base: &Sketch,
    table: &Table,
    row: usize,
) -> (Sketch, Result<SketchReport>) {
    let mut s = base.clone();
    let outcome = table
        .row(row)
        .try_for_each(|(n, v)| s.define_parameter(n, v).map(|_| ()))
        .and_then(|()| worker.solve_dirty(&mut s));
    (s, outcome)
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

/// The row of results of a solved variant.
fn result_of(row: usize, (s, outcome): &(Sketch, Result<SketchReport>)) -> VariantResult {
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

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

    use super::*;
    use crate::constraints::{Distance, Fixed};
    use crate::PointRef;
    use nalgebra::Point2;

    /// A fixed point, a second at `gap` from it and a third at `reach` from the second: one
    /// nonlinear component reading both parameters.
    fn chain() -> Sketch {
        let mut s = Sketch::new();
        let a = s.add_point(Point2::new(0.0, 0.0)).unwrap();
        let b = s.add_point(Point2::new(1.2, 0.3)).unwrap();
        let c = s.add_point(Point2::new(2.0, 1.1)).unwrap();
        s.define_parameter("gap", 1.0).unwrap();
        s.define_parameter("reach", 1.0).unwrap();
        s.add_constraint(Fixed::point(PointRef::Point(a))).unwrap();
        let d = s
            .add_constraint(Distance {
                a: PointRef::Point(a),
                b: PointRef::Point(b),
                distance: 1.0,
            })
            .unwrap();
        s.bind_dimension(d, "distance", "gap").unwrap();
        let e = s
            .add_constraint(Distance {
                a: PointRef::Point(b),
                b: PointRef::Point(c),
                distance: 1.0,
            })
            .unwrap();
        s.bind_dimension(e, "distance", "reach * 2 - gap").unwrap();
        s
    }

    fn diffuser() -> Sketch {
        let path = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../examples/sketches/diffuser_parametric.json"
        );
        crate::file::from_json(&std::fs::read_to_string(path).unwrap()).unwrap()
    }

    /// Solves every row of `table` on one sweep worker and checks each against the variant
    /// solved alone (a copy of `base`, the row's parameters set, [`Sketch::solve`]): the same
    /// outcome, every point within 1e-12, the same free parameters and residuals. Returns how
    /// many components the worker solved on a kept problem.
    fn sweep_equals_each_alone(base: &Sketch, table: &Table) -> usize {
        let mut worker = Worker::for_sweep(swept_by(base, table));
        for i in 0..table.rows() {
            let (swept_sketch, outcome) = solve_row(&mut worker, base, table, i);
            let mut alone = base.clone();
            let alone_outcome = table
                .row(i)
                .try_for_each(|(n, v)| alone.define_parameter(n, v).map(|_| ()))
                .and_then(|()| alone.solve());
            assert_eq!(outcome.is_ok(), alone_outcome.is_ok(), "row {i}");
            for ((id, e), (id2, e2)) in swept_sketch.entities().zip(alone.entities()) {
                assert_eq!(id, id2);
                for (p, q) in e.points().iter().zip(e2.points()) {
                    assert!((p - q).norm() <= 1e-12, "row {i}, {id}: {p} vs {q}");
                }
            }
            let (r, r_alone) = (
                result_of(i, &(swept_sketch, outcome)),
                result_of(i, &(alone, alone_outcome)),
            );
            assert_eq!(r.free.len(), r_alone.free.len(), "row {i}");
            for (f, g) in r.free.iter().zip(&r_alone.free) {
                assert_eq!((f.0, &f.1), (g.0, &g.1));
                assert!((f.2 - g.2).abs() <= 1e-12, "row {i}: {f:?} vs {g:?}");
            }
            assert!(
                (r.max_residual - r_alone.max_residual).abs() <= 1e-12
                    || (r.max_residual.is_nan() && r_alone.max_residual.is_nan()),
                "row {i}"
            );
            assert_eq!(r.error, r_alone.error, "row {i}");
        }
        worker.reused()
    }

    #[test]
    fn a_sweep_reuses_the_prepared_component_and_answers_as_each_variant_alone() {
        let base = chain();
        let gaps: Vec<f64> = (0..8).map(|i| 0.6 + 0.15 * f64::from(i)).collect();
        let reaches: Vec<f64> = (0..8).map(|i| 1.3 - 0.05 * f64::from(i)).collect();
        let table = Table::try_new(vec![("gap".into(), gaps), ("reach".into(), reaches)]).unwrap();
        // One component, compiled for the first row and solved on that problem for the 7 others.
        assert_eq!(sweep_equals_each_alone(&base, &table), 7);
        // A row the sketch refuses (a negative distance) stays on its row and the rows after
        // it still take the kept problem of the last solved variant.
        let table = Table::try_new(vec![("gap".into(), vec![1.0, -1.0, 1.5, 0.8])]).unwrap();
        assert_eq!(sweep_equals_each_alone(&base, &table), 2);
    }

    #[test]
    fn a_sweep_over_contacts_answers_as_each_variant_alone() {
        // Circles placed and sized by parameters, a curve tangent to one at a free parameter:
        // its pieces read a free parameter, so its component is built again (never replaced in
        // place); the answers are those of each variant alone all the same.
        let base = diffuser();
        let table = Table::try_new(vec![
            ("r3".into(), vec![0.065, 0.07, 0.075, 0.072]),
            ("y3".into(), vec![0.035, 0.04, 0.045, 0.041]),
        ])
        .unwrap();
        sweep_equals_each_alone(&base, &table);
    }
}
