//! What the linearized constraints leave free: the mobility of a few combinations of unknowns
//! (a dragged point), and the multipliers of the rows at a solution.
//!
//! **Mobility.** For combinations p = E·x of the unknowns (E k × N: a point's two coordinates,
//! say) the moves the constraints allow to first order are δp = E·A·δz with J·δz = 0. Their span
//! is the range of the k × k matrix G = E_z·P_W·W⁻¹·E_zᵀ, E_z = E·A, P_W the W-orthogonal
//! projector onto the null space of the independent rows of J (W⁻¹·E_zᵀ projected by one
//! factorization of J·W⁻¹·Jᵀ); the unconstrained mobility is trace(E_z·W⁻¹·E_zᵀ).
//!
//! **Multipliers.** At a solution z* of the minimum-norm problem min ½‖z − z₀‖²_W subject to
//! g(z) = 0, W·(z* − z₀) = Jᵀ·μ, so μ = (J·W⁻¹·Jᵀ)⁻¹·J·(z* − z₀): one factorization, one solve.
//! The sign of an inequality row's μ says whether it binds.

use crate::analysis::rank::analyze;
use crate::linalg::min_norm::MinNormFactorization;
use crate::model::errors::{Error, Result};
use crate::model::ids::{ConstraintId, UnknownId};
use crate::model::options::Options;
use crate::model::problem::Problem;

/// The mobility of combinations of unknowns under a problem's linearized constraints (see the
/// module documentation).
#[derive(Debug, Clone, PartialEq)]
pub struct Mobility {
    /// G, k × k row major (k the number of combinations): its range is the set of moves the
    /// constraints allow.
    pub gram: Vec<f64>,
    /// trace(E_z·W⁻¹·E_zᵀ): the mobility without constraints, for relative tests.
    pub scale: f64,
    /// The constraints whose linearized rows conflict at the current values (dependent and
    /// inconsistent), when the rows were analysed (small problems); empty otherwise.
    pub conflicting: Vec<ConstraintId>,
}

/// The mobility of the combinations `rows` (each a list of (unknown, coefficient)) of the
/// problem's unknowns at its current values under every constraint but those in `ignore` (a
/// dragged point's own pin, say): `None` when the rows of a large problem turn out dependent
/// (no cheap answer then; small problems are analysed and keep their independent rows).
///
/// ```
/// use camber_solve::{mobility, scalar::cst, ConstraintId, Options, Problem, Residual, Scalar};
/// /// y = 0: the point stays on the x axis.
/// #[derive(Debug)]
/// struct OnAxis;
/// impl Residual for OnAxis {
///     fn name(&self) -> &str { "on axis" }
///     fn dim(&self) -> usize { 1 }
///     fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) { out[0] = x[0][1] - cst(0.0); }
///     fn is_affine(&self) -> bool { true }
/// }
/// let mut p = Problem::new();
/// let b = p.add_block(&[1.0, 0.0])?;
/// p.add_residual(OnAxis, &[b], ConstraintId(1))?;
/// let (ux, uy) = (p.unknown(b, 0)?, p.unknown(b, 1)?);
/// let m = mobility(&p, &[&[(ux, 1.0)], &[(uy, 1.0)]], &[], &Options::default())?.expect("small");
/// // Free along x, held along y.
/// assert!((m.gram[0] - 1.0).abs() < 1e-12 && m.gram[3].abs() < 1e-12);
/// # Ok::<(), camber_solve::Error>(())
/// ```
///
/// # Errors
/// Those of [`Problem::linearize`]; [`Error::UnknownUnknown`] for an unknown the problem did
/// not issue.
pub fn mobility(
    problem: &Problem,
    rows: &[&[(UnknownId, f64)]],
    ignore: &[ConstraintId],
    options: &Options,
) -> Result<Option<Mobility>> {
    let mut lin = problem.linearize()?;
    if lin.row_owner.iter().any(|o| ignore.contains(o)) {
        let keep: Vec<usize> = (0..lin.row_owner.len())
            .filter(|i| !ignore.contains(&lin.row_owner[*i]))
            .collect();
        lin.jacobian = lin.jacobian.select_rows(&keep);
        lin.g = keep.iter().map(|i| lin.g[*i]).collect();
        lin.row_owner = keep.iter().map(|i| lin.row_owner[*i]).collect();
        lin.row_residual = keep.iter().map(|i| lin.row_residual[*i]).collect();
    }
    let (m, n) = (lin.g.len(), lin.map.len());
    let k = rows.len();
    // E_z = E·A, k × n.
    let mut e = vec![vec![0.0; n]; k];
    for (row, terms) in e.iter_mut().zip(rows) {
        for (u, c) in *terms {
            if u.0 >= problem.num_unknowns() {
                return Err(Error::UnknownUnknown {
                    index: u.0,
                    len: problem.num_unknowns(),
                });
            }
            for (col, a) in lin.map.row(u.0).0 {
                row[*col] += c * a;
            }
        }
    }
    let weights = lin.map.weights();
    let scale: f64 = e
        .iter()
        .map(|row| row.iter().zip(weights).map(|(v, w)| v * v / w).sum::<f64>())
        .sum();
    let (independent, conflicting) = if m.saturating_mul(n) <= options.dense_analysis_max_entries {
        let a = analyze(&lin, options.rank_tolerance, options.tolerance)?;
        (a.rows.independent, a.conflicting)
    } else {
        ((0..m).collect(), Vec::new())
    };
    let mut gram = vec![0.0; k * k];
    if independent.is_empty() {
        for i in 0..k {
            for j in 0..k {
                gram[i * k + j] = e[i]
                    .iter()
                    .zip(&e[j])
                    .zip(weights)
                    .map(|((a, b), w)| a * b / w)
                    .sum();
            }
        }
        return Ok(Some(Mobility {
            gram,
            scale,
            conflicting,
        }));
    }
    let mut f = match MinNormFactorization::try_auto(
        &lin.jacobian.select_rows(&independent),
        weights,
        options.dense_max_unknowns,
    ) {
        Ok(f) => f,
        Err(Error::RankDeficient { .. }) => return Ok(None),
        Err(e) => return Err(e),
    };
    let (mut out, mut y) = (vec![0.0; n], vec![0.0; f.rows()]);
    for j in 0..k {
        f.project(&e[j], &mut out, &mut y)?;
        for i in 0..k {
            gram[i * k + j] = e[i].iter().zip(&out).map(|(a, b)| a * b).sum();
        }
    }
    Ok(Some(Mobility {
        gram,
        scale,
        conflicting,
    }))
}

/// The multipliers μ of every row at the problem's current values, taken as the solution of
/// the minimum-norm problem from `start` (reduced unknowns, in the order of
/// [`crate::ReducedMap::vars`]): μ = (J·W⁻¹·Jᵀ)⁻¹·J·(z − z₀). `None` when the rows are
/// dependent there (no multiplier to read) or `start` does not match the problem.
///
/// ```
/// use camber_solve::{multipliers, scalar::cst, ConstraintId, Options, Problem, Residual, Scalar};
/// /// x = 1.
/// #[derive(Debug)]
/// struct XIsOne;
/// impl Residual for XIsOne {
///     fn name(&self) -> &str { "x is one" }
///     fn dim(&self) -> usize { 1 }
///     fn eval<T: Scalar>(&self, x: &[&[T]], out: &mut [T]) { out[0] = x[0][0] - cst(1.0); }
///     fn is_affine(&self) -> bool { true }
/// }
/// let mut p = Problem::new();
/// let b = p.add_block(&[1.0])?;
/// p.add_residual(XIsOne, &[b], ConstraintId(1))?;
/// // Solved from x = 3: the row pulled x back by 2.
/// let mu = multipliers(&p, &[3.0], &Options::default())?.expect("independent");
/// assert!((mu[0] + 2.0).abs() < 1e-12);
/// # Ok::<(), camber_solve::Error>(())
/// ```
///
/// # Errors
/// Those of [`Problem::linearize`].
pub fn multipliers(
    problem: &Problem,
    start: &[f64],
    options: &Options,
) -> Result<Option<Vec<f64>>> {
    let lin = problem.linearize()?;
    let (m, n) = (lin.jacobian.nrows(), lin.jacobian.ncols());
    let z = lin.map.z0();
    if z.len() != start.len() {
        return Ok(None);
    }
    let w = lin.map.weights();
    // project(v) with v = W·(z* − z₀) returns y = (J·W⁻¹·Jᵀ)⁻¹·J·(z* − z₀) = μ.
    let v: Vec<f64> = (0..n).map(|k| w[k] * (z[k] - start[k])).collect();
    let Ok(mut f) = MinNormFactorization::try_auto(&lin.jacobian, w, options.dense_max_unknowns)
    else {
        return Ok(None);
    };
    let (mut out, mut mu) = (vec![0.0; n], vec![0.0; m]);
    f.project(&v, &mut out, &mut mu)?;
    Ok(Some(mu))
}
