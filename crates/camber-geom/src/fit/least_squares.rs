//! Least squares on given knots and parameters, with end control points that are free, fixed,
//! or constrained to a line (the shared tangent of a split fit).
//!
//! Every control point is P_i = a_i + B_i x_i with unknowns x_i: a free point has a_i = 0 and
//! B_i = I (D unknowns), a fixed one no unknown, a point on the line a + βd has B_i = d (one
//! unknown β). The residual of data point Q_k at parameter ū_k is
//! r_k = Q_k − Σ_i N_{i,p}(ū_k) (a_i + B_i x_i), and Σ_k |r_k|² is minimised through the normal
//! equations JᵀJ x = Jᵀr₀. Numbering the unknowns in control-point order makes JᵀJ banded
//! (a data point touches the p + 1 control points of its span, at most D(p + 1) unknowns), so
//! the system is stored and eliminated by its band; a span without data makes it singular,
//! and then the minimum-norm solution of a dense SVD is taken (up to [`DENSE_FALLBACK_MAX`]
//! unknowns), or, when the caller has a curve to fall back on ([`OnSingular::Fail`]), the
//! system is reported singular at once: the SVD costs O(size³), far more than the O(size) the
//! rest of a fit charges to its budget.

use nalgebra::{DMatrix, Point, SVector};
use smallvec::SmallVec;

use crate::banded::BandedMatrix;
use crate::basis::INLINE_DEGREE;
use crate::bspline::BSplineCurve;
use crate::errors::{Error, Result};
use crate::knots::KnotVector;
use crate::scalar::{cst, re, Scalar};

/// The largest least-squares system (unknowns) solved by a dense SVD when its normal equations
/// are singular (a span without data): 2,000 unknowns is a 32 MB copy and a few seconds;
/// beyond that a singular system is reported instead.
pub(crate) const DENSE_FALLBACK_MAX: usize = 2_000;

/// What a least-squares fit does when its normal equations are singular (a span without data).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum OnSingular {
    /// The minimum-norm solution by a dense SVD, up to [`DENSE_FALLBACK_MAX`] unknowns.
    MinimumNorm,
    /// [`Error::SingularSystem`] at once (the caller keeps a curve it has).
    Fail,
}

/// What a control point of a least-squares fit may do.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Role<T: Scalar, const D: usize> {
    /// Any position (D unknowns).
    Free,
    /// This position (no unknown).
    Fixed(Point<T, D>),
    /// origin + β·direction for any β (one unknown).
    OnLine(Point<T, D>, SVector<T, D>),
}

/// The roles of the first control points (`start[0]` is P₀, `start[1]` is P₁, …) and of the
/// last ones (`end[0]` is P_n, `end[1]` is P_{n−1}, …); all others are free.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct EndRoles<T: Scalar, const D: usize> {
    /// Roles from the start inwards.
    pub start: Vec<Role<T, D>>,
    /// Roles from the end inwards.
    pub end: Vec<Role<T, D>>,
}

impl<T: Scalar, const D: usize> EndRoles<T, D> {
    /// The role of control point `i` of `count`.
    fn role(&self, i: usize, count: usize) -> Role<T, D> {
        if let Some(r) = self.start.get(i) {
            return *r;
        }
        let from_end = count - 1 - i;
        self.end.get(from_end).copied().unwrap_or(Role::Free)
    }

    /// How many control points the roles need at least (start and end roles never overlap).
    pub fn needed(&self) -> usize {
        self.start.len() + self.end.len()
    }
}

/// The coefficients of one data point's row: (unknown index, ∂(Σ N_i P_i)/∂x_j as a vector).
type RowEntries<T, const D: usize> = SmallVec<[(usize, SVector<T, D>); 2 * (INLINE_DEGREE + 1)]>;

/// The least-squares B-spline of `degree` on `knots` (clamped, n + 1 = len − p − 1 control
/// points) for data `points` at `parameters` (inside the knots' domain), with the end roles.
///
/// Errors: [`Error::TooFewControlPoints`] when the roles need more control points than the
/// knots give, [`Error::SingularSystem`] when the normal equations cannot be solved (at once
/// with [`OnSingular::Fail`]).
pub(crate) fn fit_on_knots<T: Scalar, const D: usize>(
    points: &[Point<T, D>],
    parameters: &[T],
    degree: usize,
    knots: KnotVector<T>,
    roles: &EndRoles<T, D>,
    on_singular: OnSingular,
) -> Result<BSplineCurve<T, D>> {
    let p = degree;
    let count = knots.len().saturating_sub(p + 1);
    if count < (p + 1).max(roles.needed()) {
        return Err(Error::TooFewControlPoints {
            degree,
            needed: (p + 1).max(roles.needed()),
            found: count,
        });
    }
    let coupled = roles
        .start
        .iter()
        .chain(&roles.end)
        .any(|r| matches!(r, Role::OnLine(..)));
    if !coupled {
        return fit_separable(points, parameters, degree, knots, roles, count, on_singular);
    }
    // Unknown numbering: offsets[i] is the first unknown of control point i.
    let mut offsets = Vec::with_capacity(count + 1);
    let mut size = 0usize;
    for i in 0..count {
        offsets.push(size);
        size += match roles.role(i, count) {
            Role::Free => D,
            Role::Fixed(_) => 0,
            Role::OnLine(..) => 1,
        };
    }
    offsets.push(size);
    let mut control: Vec<Point<T, D>> = (0..count)
        .map(|i| match roles.role(i, count) {
            Role::Fixed(q) | Role::OnLine(q, _) => q,
            Role::Free => Point::origin(),
        })
        .collect();
    if size == 0 {
        return BSplineCurve::try_new(p, knots, control);
    }
    // A data point's unknowns lie within those of p + 1 consecutive control points.
    let band = (0..count.saturating_sub(p))
        .map(|i| offsets[i + p + 1] - offsets[i])
        .max()
        .unwrap_or(size)
        .max(1)
        - 1;
    let mut normal = BandedMatrix::<T>::zeros(size, band, band);
    let mut rhs = DMatrix::<T>::zeros(size, 1);
    let mut basis: SmallVec<[T; INLINE_DEGREE + 1]> = SmallVec::from_elem(T::zero(), p + 1);
    let singular = Error::SingularSystem {
        what: "least-squares",
    };
    let mut span = p;
    for (q, &u) in points.iter().zip(parameters) {
        span = knots.find_span_from(p, u, span);
        knots.basis_functions(span, u, p, &mut basis);
        let first = span - p;
        let mut residual = q.coords;
        let mut entries: RowEntries<T, D> = SmallVec::new();
        for (j, &n) in basis.iter().enumerate() {
            let i = first + j;
            match roles.role(i, count) {
                Role::Free => {
                    for c in 0..D {
                        let mut e = SVector::<T, D>::zeros();
                        e[c] = n;
                        entries.push((offsets[i] + c, e));
                    }
                }
                Role::Fixed(a) => residual -= a.coords * n,
                Role::OnLine(a, d) => {
                    residual -= a.coords * n;
                    entries.push((offsets[i], d * n));
                }
            }
        }
        for &(r, er) in &entries {
            for &(c, ec) in &entries {
                normal.add(r, c, er.dot(&ec)).ok_or(singular.clone())?;
            }
            rhs[(r, 0)] += er.dot(&residual);
        }
    }
    let solution = solve_normal(normal, rhs, size, on_singular)?;
    for (i, point) in control.iter_mut().enumerate() {
        let o = offsets[i];
        match roles.role(i, count) {
            Role::Free => {
                for c in 0..D {
                    point.coords[c] = solution[(o + c, 0)];
                }
            }
            Role::Fixed(_) => {}
            Role::OnLine(a, d) => *point = a + d * solution[(o, 0)],
        }
    }
    BSplineCurve::try_new(p, knots, control)
}

/// [`fit_on_knots`] when every control point is free or fixed: the coordinates separate, so one
/// banded system of half-width p in the free control points serves all D right-hand sides.
fn fit_separable<T: Scalar, const D: usize>(
    points: &[Point<T, D>],
    parameters: &[T],
    degree: usize,
    knots: KnotVector<T>,
    roles: &EndRoles<T, D>,
    count: usize,
    on_singular: OnSingular,
) -> Result<BSplineCurve<T, D>> {
    let p = degree;
    let fixed: Vec<Option<Point<T, D>>> = (0..count)
        .map(|i| match roles.role(i, count) {
            Role::Fixed(q) => Some(q),
            _ => None,
        })
        .collect();
    // Free control points are numbered in order; fixed ones have no unknown.
    let mut index = vec![usize::MAX; count];
    let mut size = 0;
    for (i, f) in fixed.iter().enumerate() {
        if f.is_none() {
            index[i] = size;
            size += 1;
        }
    }
    let mut control: Vec<Point<T, D>> = fixed
        .iter()
        .map(|f| f.unwrap_or_else(Point::origin))
        .collect();
    if size == 0 {
        return BSplineCurve::try_new(p, knots, control);
    }
    let mut normal = BandedMatrix::<T>::zeros(size, p, p);
    let mut rhs = DMatrix::<T>::zeros(size, D);
    let mut basis: SmallVec<[T; INLINE_DEGREE + 1]> = SmallVec::from_elem(T::zero(), p + 1);
    let singular = Error::SingularSystem {
        what: "least-squares",
    };
    let mut span = p;
    for (q, &u) in points.iter().zip(parameters) {
        span = knots.find_span_from(p, u, span);
        knots.basis_functions(span, u, p, &mut basis);
        let first = span - p;
        let base = index[first];
        if base != usize::MAX && index[first + p] == base + p {
            // Every active control point free (so numbered base … base + p): the point adds
            // N·Nᵀ to one block.
            normal.add_outer(base, &basis).ok_or(singular.clone())?;
            for (j, &nj) in basis.iter().enumerate() {
                for d in 0..D {
                    rhs[(base + j, d)] += nj * q.coords[d];
                }
            }
            continue;
        }
        let mut residual = q.coords;
        for (j, &n) in basis.iter().enumerate() {
            if let Some(a) = fixed[first + j] {
                residual -= a.coords * n;
            }
        }
        for (j, &nj) in basis.iter().enumerate() {
            let r = index[first + j];
            if r == usize::MAX || re(nj) == 0.0 {
                continue;
            }
            for (l, &nl) in basis.iter().enumerate() {
                let c = index[first + l];
                if c != usize::MAX {
                    normal.add(r, c, nj * nl).ok_or(singular.clone())?;
                }
            }
            for d in 0..D {
                rhs[(r, d)] += nj * residual[d];
            }
        }
    }
    let solution = solve_normal(normal, rhs, size, on_singular)?;
    for (i, point) in control.iter_mut().enumerate() {
        if index[i] != usize::MAX {
            for d in 0..D {
                point.coords[d] = solution[(index[i], d)];
            }
        }
    }
    BSplineCurve::try_new(p, knots, control)
}

/// Solves the normal equations by band elimination, or, with [`OnSingular::MinimumNorm`], by
/// the dense SVD's minimum-norm solution when they are singular and small enough.
fn solve_normal<T: Scalar>(
    normal: BandedMatrix<T>,
    rhs: DMatrix<T>,
    size: usize,
    on_singular: OnSingular,
) -> Result<DMatrix<T>> {
    let singular = Error::SingularSystem {
        what: "least-squares",
    };
    let solution = match normal.clone().solve(rhs.clone()) {
        Some(x) => x,
        None if on_singular == OnSingular::MinimumNorm && size <= DENSE_FALLBACK_MAX => normal
            .to_dense()
            .svd(true, true)
            .solve(&rhs, cst::<T>(1e-13))
            .map_err(|_| singular.clone())?,
        None => return Err(singular),
    };
    if solution.iter().any(|v| !re(*v).is_finite()) {
        return Err(singular);
    }
    Ok(solution)
}

/// The clamped knot vector on [0, 1] with the given interior knots (increasing, inside).
pub(crate) fn clamped_knots<T: Scalar>(degree: usize, interior: &[T]) -> KnotVector<T> {
    let mut knots = Vec::with_capacity(interior.len() + 2 * degree + 2);
    knots.extend(std::iter::repeat_n(T::zero(), degree + 1));
    knots.extend_from_slice(interior);
    knots.extend(std::iter::repeat_n(T::one(), degree + 1));
    KnotVector::new_unchecked(knots)
}
