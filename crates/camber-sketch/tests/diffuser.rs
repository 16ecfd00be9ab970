//! The diffuser airfoil (workload W2 `bspline7`): a clamped cubic B-spline with 7 control points
//! tangent to three circles, solved from the rough start and from seeded perturbations, each
//! result checked by the workload's own validity test written here independently of the solver.

// Fixture helpers outside #[test] functions unwrap results of fixed, valid inputs.
#![allow(clippy::unwrap_used)]

use camber_geom::queries::closest_point;
use camber_geom::ParametricCurve;
use camber_sketch::constraints::Coincident;
use camber_sketch::{Entity, PointRef, Sketch};
use camber_workloads::{w2_bspline7, W2, W2_CIRCLES};
use nalgebra::Point2;

/// The W2 validity check (tolerance 1e-6): ends on their circles, tangent ⟂ radius at both
/// ends, min distance centre–curve = r for TH and ≥ r for LE and TE, TH contact on the upper
/// half.
fn valid(s: &Sketch, w: &W2) -> Result<(), String> {
    let tol = 1e-6;
    let Entity::BSpline(curve) = s.entity(w.curve).unwrap() else {
        return Err("not a B-spline".into());
    };
    let (a, b) = curve.domain();
    for (k, u) in [(0, a), (2, b)] {
        let (c, r) = W2_CIRCLES[k];
        let (p, t) = curve.point_and_derivative(u).unwrap();
        let v = p - Point2::new(c[0], c[1]);
        if (v.norm() - r).abs() > tol {
            return Err(format!("end {k} off its circle by {}", v.norm() - r));
        }
        if (v.dot(&t) / (v.norm() * t.norm())).abs() > tol {
            return Err(format!("end {k} tangent not perpendicular to the radius"));
        }
    }
    for (k, (c, r)) in W2_CIRCLES.iter().enumerate() {
        let cp = closest_point(curve, &Point2::new(c[0], c[1])).unwrap();
        let gap = cp.distance - r;
        if k == 1 {
            if gap.abs() > tol {
                return Err(format!("TH gap {gap}"));
            }
            if cp.point.y < c[1] {
                return Err(format!("TH contact on the lower half at {:?}", cp.point));
            }
        } else if gap < -tol {
            return Err(format!("circle {k} crossed by {gap}"));
        }
    }
    Ok(())
}

/// A small seeded generator (splitmix64) of uniform numbers in [−1, 1].
struct Noise(u64);

impl Noise {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }
}

fn base() -> (Sketch, W2) {
    let (mut s, w) = w2_bspline7().unwrap();
    let report = s.solve().unwrap();
    assert_eq!(report.components.len(), 1);
    (s, w)
}

#[test]
fn the_rough_start_solves_to_a_valid_airfoil() {
    let (s, w) = base();
    valid(&s, &w).unwrap();
}

/// Runs `trials` perturbations of size δ from the base solution; returns the valid count. A
/// solve that reports success must leave a valid airfoil, and a refused one must write
/// nothing.
fn perturbed(delta: f64, trials: usize, seed: u64) -> usize {
    let (s0, w) = base();
    let mut noise = Noise(seed);
    let mut ok = 0;
    for _ in 0..trials {
        let mut s = s0.clone();
        for j in 0..7 {
            let p = s.point(PointRef::Control(w.curve, j)).unwrap();
            let q = Point2::new(p.x + delta * noise.next(), p.y + delta * noise.next());
            s.set_point(PointRef::Control(w.curve, j), q).unwrap();
        }
        let before = s.clone();
        match s.solve() {
            Ok(_) => {
                valid(&s, &w).unwrap();
                ok += 1;
            }
            Err(_) => assert_eq!(
                s.entities().collect::<Vec<_>>(),
                before.entities().collect::<Vec<_>>()
            ),
        }
    }
    ok
}

#[test]
fn small_perturbations_solve_valid() {
    let n = 100;
    let ok = perturbed(0.01, n, 1);
    assert!(ok >= n - 1, "{ok} of {n} valid");
}

#[test]
fn large_perturbations_solve_valid() {
    let n = 100;
    let ok = perturbed(0.05, n, 2);
    // Issue 4 asks 99 of 100. The hard starts are at the leading-edge contact (radius 0.03,
    // noise up to 0.05): the nearest curve would cross the LE circle beside the contact (a
    // clearance row makes it touch there instead) or collapse the first leg into a cusp (the
    // speed floor keeps a quarter of the leg's starting speed); see camber_sketch::clearance.
    assert!(ok >= 99, "{ok} of {n} valid");
}

#[test]
fn dragging_a_control_point_keeps_the_contacts_without_jumps() {
    let (mut s, w) = base();
    let dragged = PointRef::Control(w.curve, 3);
    let start = s.point(dragged).unwrap();
    let mut d = s.drag(dragged).unwrap();
    let step = 0.0002;
    let mut prev: Vec<Point2<f64>> = (0..7)
        .map(|j| d.point(PointRef::Control(w.curve, j)).unwrap())
        .collect();
    for k in 1..=200 {
        let target = Point2::new(start.x, start.y + step * f64::from(k));
        d.update(target).unwrap();
        let now: Vec<Point2<f64>> = (0..7)
            .map(|j| d.point(PointRef::Control(w.curve, j)).unwrap())
            .collect();
        let jump = now
            .iter()
            .zip(&prev)
            .map(|(a, b)| (a - b).norm())
            .fold(0.0, f64::max);
        assert!(jump < 10.0 * step, "step {k}: a control point moved {jump}");
        prev = now;
    }
    d.finish(&mut s).unwrap();
    valid(&s, &w).unwrap();
    assert!((s.point(dragged).unwrap().y - start.y - 200.0 * step).abs() < 1e-12);
}

#[test]
fn a_failed_solve_leaves_the_sketch_unchanged() {
    let (mut s, w) = base();
    // P1 on top of P0: the start tangent vanishes, so no tangency at the LE circle is
    // possible (a cusp) and the solve must fail without writing anything.
    s.add_constraint(camber_sketch::Constraint::Coincident(Coincident {
        a: PointRef::Control(w.curve, 0),
        b: PointRef::Control(w.curve, 1),
    }))
    .unwrap();
    let before: Vec<_> = s.entities().map(|(i, e)| (i, e.clone())).collect();
    let constraints_before: Vec<_> = s.constraints().map(|(i, c)| (i, c.clone())).collect();
    assert!(s.solve().is_err());
    let after: Vec<_> = s.entities().map(|(i, e)| (i, e.clone())).collect();
    let constraints_after: Vec<_> = s.constraints().map(|(i, c)| (i, c.clone())).collect();
    assert_eq!(before, after);
    assert_eq!(constraints_before, constraints_after);
}

/// W2 `2cubic` from its rough start, then `trials` seeded perturbations of size δ of the 7
/// points Q₀…Q₆ (the joint Q₃ moved as one point); returns the valid count. Refused starts
/// write nothing.
fn two_cubics_perturbed(delta: f64, trials: usize, seed: u64) -> usize {
    use camber_workloads::{w2_2cubic, w2_2cubic_valid};
    let (mut s0, curves, _) = w2_2cubic().unwrap();
    s0.solve().unwrap();
    assert!(w2_2cubic_valid(&s0, curves));
    let refs = |j: usize| -> Vec<PointRef> {
        match j {
            0..=2 => vec![PointRef::Control(curves[0], j)],
            3 => vec![
                PointRef::Control(curves[0], 3),
                PointRef::Control(curves[1], 0),
            ],
            _ => vec![PointRef::Control(curves[1], j - 3)],
        }
    };
    let mut noise = Noise(seed);
    let mut ok = 0;
    for _ in 0..trials {
        let mut s = s0.clone();
        for j in 0..7 {
            let (dx, dy) = (delta * noise.next(), delta * noise.next());
            for r in refs(j) {
                let p = s.point(r).unwrap();
                s.set_point(r, Point2::new(p.x + dx, p.y + dy)).unwrap();
            }
        }
        let before = s.clone();
        match s.solve() {
            Ok(_) if w2_2cubic_valid(&s, curves) => ok += 1,
            Ok(_) => panic!("δ = {delta}: a solve reported success on an invalid airfoil"),
            Err(_) => assert_eq!(
                s.entities().collect::<Vec<_>>(),
                before.entities().collect::<Vec<_>>()
            ),
        }
    }
    ok
}

#[test]
fn two_cubics_small_perturbations_solve_valid() {
    let ok = two_cubics_perturbed(0.01, 100, 3);
    assert!(ok >= 99, "{ok} of 100 valid");
}

#[test]
fn two_cubics_large_perturbations_solve_valid() {
    let ok = two_cubics_perturbed(0.05, 100, 4);
    assert!(ok >= 99, "{ok} of 100 valid");
}

/// The selected solve's displacement is no worse (within 1 %) than SLSQP's from the same
/// perturbed start, both minimising ½‖z − z₀‖² over the same honest problem (the active rows
/// of crossing or collapsing contacts come from the sketch, whichever solver runs): 20 starts
/// per δ for each representation, every one solved by both.
#[test]
fn displacement_is_no_worse_than_slsqp() {
    use camber_workloads::{w2_2cubic, w2_2cubic_perturbed, w2_perturbed};
    let (s0, w) = base();
    let (mut c0, curves, _) = w2_2cubic().unwrap();
    c0.solve().unwrap();
    let mut compared = 0;
    for (delta, seed) in [(0.01, 5), (0.05, 6)] {
        let mut starts = w2_perturbed(&s0, &w, delta, 20, seed).unwrap();
        starts.extend(w2_2cubic_perturbed(&c0, curves, delta, 20, seed).unwrap());
        for s in starts {
            let mut ours = s.clone();
            let mut reference = s;
            reference.set_options(
                camber_sketch::solve::default_options()
                    .with_force(Some(camber_solve::SolverChoice::Slsqp)),
            );
            let (a, b) = (ours.solve().unwrap(), reference.solve().unwrap());
            let (a, b) = (
                a.components[0].report.displacement_norm,
                b.components[0].report.displacement_norm,
            );
            assert!(a <= 1.01 * b + 1e-12, "δ = {delta}: {a} vs SLSQP {b}");
            compared += 1;
        }
    }
    assert_eq!(compared, 80);
}
