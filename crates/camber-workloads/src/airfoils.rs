//! NACA four- and five-digit airfoil sections from their defining formulas, as point lists in
//! the Selig order (trailing edge over the upper surface to the leading edge and back along the
//! lower surface): the data of the fitting benchmarks.
//!
//! Thickness (chord 1, x ∈ [0, 1], t the thickness ratio, open trailing edge):
//! y_t = 5t(0.2969√x − 0.1260x − 0.3516x² + 0.2843x³ − 0.1015x⁴).
//! Four-digit camber line MPTT (m = M/100, p = P/10): y_c = m/p²(2px − x²) for x < p and
//! m/(1 − p)²((1 − 2p) + 2px − x²) after. Five-digit LPSTT (standard, S = 0): with r and k₁
//! of the camber position P (tabulated for a design lift of 0.3, scaled by 0.15·L/0.3),
//! y_c = k₁/6 (x³ − 3rx² + r²(3 − r)x) for x < r and k₁r³/6 (1 − x) after. The surfaces are
//! offset from the camber line along its normal: x_u = x − y_t sin θ, y_u = y_c + y_t cos θ,
//! x_l = x + y_t sin θ, y_l = y_c − y_t cos θ with tan θ = y_c′.
//!
//! ```
//! use camber_workloads::airfoils::{naca, Spacing};
//! let pts = naca("2412", 101, Spacing::Cosine).unwrap();
//! assert_eq!(pts.len(), 101);
//! // The leading edge is the origin; the trailing edge points lie near (1, 0).
//! assert!(pts[50].coords.norm() < 1e-15);
//! assert!((pts[0].x - 1.0).abs() < 1e-3 && (pts[100].x - 1.0).abs() < 1e-3);
//! ```

use nalgebra::Point2;

/// How the chordwise stations are spaced.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Spacing {
    /// x = (1 − cos β)/2 for equal steps of β ∈ [0, π]: dense at both edges.
    Cosine,
    /// Equal steps of x.
    Uniform,
}

/// The five-digit camber lines of design lift 0.3: camber position digit → (r, k₁).
const FIVE_DIGIT: [(f64, f64); 5] = [
    (0.0580, 361.4),
    (0.1260, 51.64),
    (0.2025, 15.957),
    (0.2900, 6.643),
    (0.3910, 3.230),
];

/// The half thickness y_t at x for thickness ratio t.
fn thickness(x: f64, t: f64) -> f64 {
    5.0 * t
        * (0.2969 * x.sqrt() - 0.1260 * x - 0.3516 * x * x + 0.2843 * x.powi(3)
            - 0.1015 * x.powi(4))
}

/// The camber line y_c and its slope at x, or None for a code that is not a four-digit or a
/// standard five-digit section.
fn camber_line(digits: &[u32], x: f64) -> Option<(f64, f64)> {
    match digits {
        [m, p, _, _] => {
            let (m, p) = (f64::from(*m) / 100.0, f64::from(*p) / 10.0);
            if m == 0.0 {
                return Some((0.0, 0.0));
            }
            if p <= 0.0 || p >= 1.0 {
                return None;
            }
            Some(if x < p {
                (
                    m / (p * p) * (2.0 * p * x - x * x),
                    2.0 * m / (p * p) * (p - x),
                )
            } else {
                let q = (1.0 - p) * (1.0 - p);
                (
                    m / q * ((1.0 - 2.0 * p) + 2.0 * p * x - x * x),
                    2.0 * m / q * (p - x),
                )
            })
        }
        [l, p, 0, _, _] => {
            let &(r, k1) = FIVE_DIGIT.get((*p as usize).checked_sub(1)?)?;
            let scale = f64::from(*l) * 0.15 / 0.3;
            Some(if x < r {
                (
                    scale * k1 / 6.0 * (x.powi(3) - 3.0 * r * x * x + r * r * (3.0 - r) * x),
                    scale * k1 / 6.0 * (3.0 * x * x - 6.0 * r * x + r * r * (3.0 - r)),
                )
            } else {
                (
                    scale * k1 * r.powi(3) / 6.0 * (1.0 - x),
                    -scale * k1 * r.powi(3) / 6.0,
                )
            })
        }
        _ => None,
    }
}

/// The NACA section `code` ("2412", "23012", …) with `points` points in all (at least 5), in
/// the Selig order, the leading edge (0, 0) among them (an even count drops one point from the
/// middle of the lower surface). None for an unknown code, a zero
/// thickness or fewer than 5 points.
pub fn naca(code: &str, points: usize, spacing: Spacing) -> Option<Vec<Point2<f64>>> {
    let digits: Vec<u32> = code
        .chars()
        .map(|c| c.to_digit(10))
        .collect::<Option<_>>()?;
    if points < 5 || !(4..=5).contains(&digits.len()) {
        return None;
    }
    let t = f64::from(digits[digits.len() - 2] * 10 + digits[digits.len() - 1]) / 100.0;
    if t <= 0.0 {
        return None;
    }
    // n stations a side from the leading edge to the trailing edge, shared by both sides at
    // the leading edge: 2n − 1 points, one too many for an even count (one lower-side point
    // goes, mid-side, where the spacing is widest).
    let n = points / 2 + 1;
    let station = |i: usize| {
        let s = i as f64 / (n - 1) as f64;
        match spacing {
            Spacing::Cosine => 0.5 * (1.0 - (std::f64::consts::PI * s).cos()),
            Spacing::Uniform => s,
        }
    };
    let mut upper = Vec::with_capacity(n);
    let mut lower = Vec::with_capacity(n);
    for i in 0..n {
        let x = station(i);
        let yt = thickness(x, t);
        let (yc, slope) = camber_line(&digits, x)?;
        let theta = slope.atan();
        upper.push(Point2::new(x - yt * theta.sin(), yc + yt * theta.cos()));
        lower.push(Point2::new(x + yt * theta.sin(), yc - yt * theta.cos()));
    }
    let mut out: Vec<Point2<f64>> = upper.into_iter().rev().collect();
    out.extend(lower.into_iter().skip(1));
    if points.is_multiple_of(2) {
        out.remove(n + (n - 1) / 2);
    }
    Some(out)
}

/// The sections of the fitting benchmark: eight four-digit and seven five-digit codes.
pub const BENCH_CODES: [&str; 15] = [
    "0006", "0012", "0018", "2412", "2415", "4412", "4424", "6409", "21012", "22012", "23012",
    "23015", "23018", "24012", "25012",
];

/// The point counts of the fitting benchmark (35 to 400).
pub const BENCH_COUNTS: [usize; 6] = [35, 71, 141, 201, 281, 400];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_symmetric_section_is_symmetric_and_as_thick_as_its_code() {
        let pts = naca("0012", 201, Spacing::Cosine).unwrap();
        for k in 0..100 {
            let (u, l) = (pts[k], pts[200 - k]);
            assert!((u.x - l.x).abs() < 1e-15 && (u.y + l.y).abs() < 1e-15);
        }
        let thickest = pts.iter().map(|p| p.y).fold(0.0, f64::max);
        // 12 % of the chord in all, half above: 0.06 near x = 0.3.
        assert!((thickest - 0.06).abs() < 2e-4, "{thickest}");
    }

    #[test]
    fn the_camber_lines_meet_at_their_joint() {
        for code in ["2412", "6409", "23012", "25012"] {
            let digits: Vec<u32> = code.chars().map(|c| c.to_digit(10).unwrap()).collect();
            let joint = if code.len() == 4 {
                f64::from(digits[1]) / 10.0
            } else {
                FIVE_DIGIT[digits[1] as usize - 1].0
            };
            let (a, da) = camber_line(&digits, joint - 1e-9).unwrap();
            let (b, db) = camber_line(&digits, joint + 1e-9).unwrap();
            assert!((a - b).abs() < 1e-8 && (da - db).abs() < 1e-6, "{code}");
        }
    }

    #[test]
    fn five_digit_sections_have_their_design_camber() {
        // 230xx: the maximum camber is about 1.84 % of the chord near x = 0.15.
        let (r, k1) = FIVE_DIGIT[2];
        let peak = (0..1000)
            .map(|i| {
                camber_line(&[2, 3, 0, 1, 2], f64::from(i) / 1000.0)
                    .unwrap()
                    .0
            })
            .fold(0.0, f64::max);
        assert!((peak - 0.0184).abs() < 5e-4, "{peak} {r} {k1}");
    }

    #[test]
    fn bad_codes_are_refused() {
        assert!(naca("12", 51, Spacing::Cosine).is_none());
        assert!(naca("2400", 51, Spacing::Cosine).is_none());
        assert!(naca("23712", 51, Spacing::Cosine).is_none());
        assert!(naca("2412", 3, Spacing::Cosine).is_none());
        assert!(naca("24a2", 51, Spacing::Cosine).is_none());
        assert_eq!(naca("2412", 400, Spacing::Uniform).unwrap().len(), 400);
    }
}
