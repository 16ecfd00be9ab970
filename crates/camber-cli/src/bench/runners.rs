//! One function per workload: build the sketch (untimed), time each solve or drag update on
//! its own, judge each result with the workload's validity check.

use std::collections::BTreeMap;
use std::time::{Duration, Instant};

use anyhow::{anyhow, Context, Result};
use camber_sketch::{PointRef, Sketch, SketchReport, TangentForm};
use camber_solve::SolverKind;
use camber_workloads as wl;
use indicatif::ProgressBar;
use nalgebra::Point2;

use super::{quantile, row, set_growth, Plan, Ratio, Row, Workload};

/// Tolerance of the W2, W3, W3a and W4 validity checks (WORKLOADS.md).
const TOL: f64 = 1e-6;

/// Adds one count per solved component to `solvers`.
fn count_solvers(solvers: &mut BTreeMap<String, usize>, report: &SketchReport) {
    for c in &report.components {
        let name = match c.report.solver {
            // Nothing ran: the component was already satisfied.
            SolverKind::None => "none needed".to_owned(),
            other => format!("{other:?}"),
        };
        *solvers.entry(name).or_default() += 1;
    }
}

/// W1 in both tangent forms: 200 targets on the circle of radius 0.2 through P₁, each update
/// timed, repeated `plan.w1_runs` times from the start; moved / min-norm per update.
pub(super) fn w1(plan: &Plan, bar: &ProgressBar) -> Result<Vec<Row>> {
    let mut rows = Vec::new();
    for (name, form) in [
        ("drag, row form", TangentForm::Row),
        ("drag, elimination", TangentForm::Elimination),
    ] {
        bar.set_message(format!("W1 {name}"));
        let (s, c, d) = wl::w1(form)?;
        let p1 = PointRef::Control(c, 1);
        let targets = wl::w1_targets(s.point(p1)?);
        let p3 = s.point(PointRef::Control(c, 3))?;
        let (mut times, mut ratios, mut valid, mut failed) = (Vec::new(), Vec::new(), 0, 0);
        for _ in 0..plan.w1_runs {
            let mut session = s.drag(p1)?;
            let points = |session: &camber_sketch::DragSession| -> Result<[Point2<f64>; 4]> {
                let mut out = [Point2::origin(); 4];
                for (k, p) in out.iter_mut().enumerate() {
                    *p = session.point(PointRef::Control(c, k))?;
                }
                Ok(out)
            };
            let mut before = points(&session)?;
            for &target in &targets {
                let t0 = Instant::now();
                let outcome = session.update(target).map(|_| ());
                times.push(t0.elapsed());
                bar.inc(1);
                failed += usize::from(outcome.is_err());
                let after = points(&session)?;
                if wl::w1_valid(&after, d, target, p3) {
                    valid += 1;
                }
                let least = wl::w1_min_norm_displacement(&before, d, target);
                if least > 1e-12 {
                    let moved = ((after[0] - before[0]).norm_squared()
                        + (after[2] - before[2]).norm_squared())
                    .sqrt();
                    ratios.push(moved / least);
                }
                before = after;
            }
        }
        ratios.sort_by(f64::total_cmp);
        let mut r = row(Workload::W1, name.to_owned(), &times, valid);
        r.failed = failed;
        r.timer_s = Some(timer_overhead());
        r.moved_over_min_norm = Some(Ratio {
            median: quantile(&ratios, 0.5),
            max: ratios.last().copied().unwrap_or(f64::NAN),
        });
        rows.push(r);
    }
    Ok(rows)
}

/// The median of 10,000 empty timed sections (a clock read and the elapsed time after it):
/// what each individually timed sample carries besides the work it times.
fn timer_overhead() -> f64 {
    let mut empty: Vec<f64> = (0..10_000)
        .map(|_| {
            let t0 = Instant::now();
            std::hint::black_box(t0).elapsed().as_secs_f64()
        })
        .collect();
    empty.sort_by(f64::total_cmp);
    super::quantile(&empty, 0.5)
}

/// Times one solve of each start, judging each result with `valid`.
fn trials(
    case: String,
    starts: Vec<Sketch>,
    valid: impl Fn(&Sketch) -> bool,
    bar: &ProgressBar,
) -> Row {
    let (mut times, mut ok, mut failed) = (Vec::new(), 0, 0);
    let mut solvers = BTreeMap::new();
    for mut s in starts {
        let t0 = Instant::now();
        let outcome = s.solve();
        times.push(t0.elapsed());
        bar.inc(1);
        match outcome {
            Ok(report) => count_solvers(&mut solvers, &report),
            Err(_) => failed += 1,
        }
        ok += usize::from(valid(&s));
    }
    let mut r = row(Workload::W2, case, &times, ok);
    r.failed = failed;
    r.solvers = solvers;
    r
}

/// The perturbation sizes of W2 with their seeds.
const W2_DELTAS: [(f64, u64); 2] = [(0.01, 1), (0.05, 2)];

/// W2 in both representations: the rough start solved once (untimed) as the base, then
/// `plan.w2_trials` seeded perturbed starts per δ, one timed solve each.
pub(super) fn w2(plan: &Plan, bar: &ProgressBar) -> Result<Vec<Row>> {
    let mut rows = Vec::new();
    bar.set_message("W2 bspline7");
    let (mut base, w) = wl::w2_bspline7()?;
    base.solve()
        .map_err(|e| anyhow!("{e}"))
        .context("W2 bspline7: the rough start does not solve")?;
    for (delta, seed) in W2_DELTAS {
        let starts = wl::w2_perturbed(&base, &w, delta, plan.w2_trials, seed)?;
        let case = format!("bspline7 δ={delta}");
        rows.push(trials(case, starts, |s| wl::w2_valid(s, &w), bar));
    }
    rows.push(w2_drag(&base, &w, plan, bar)?);
    bar.set_message("W2 2cubic");
    let (mut base, curves, _) = wl::w2_2cubic()?;
    base.solve()
        .map_err(|e| anyhow!("{e}"))
        .context("W2 2cubic: the rough start does not solve")?;
    for (delta, seed) in W2_DELTAS {
        let starts = wl::w2_2cubic_perturbed(&base, curves, delta, plan.w2_trials, seed)?;
        let case = format!("2cubic δ={delta}");
        rows.push(trials(
            case,
            starts,
            |s| wl::w2_2cubic_valid(s, curves),
            bar,
        ));
    }
    Ok(rows)
}

/// The diffuser's drag: control point 3 of the solved bspline7 moved up by 0.0002·k and back
/// (k = 1..100..1, 200 targets, as criterion's `w2_bspline7_drag_update`), each nonlinear update
/// timed; `plan.w1_runs` runs from the solved base. Valid: the update is kept and every
/// constraint's residual is at most 1e-6 after it.
fn w2_drag(base: &Sketch, w: &wl::W2, plan: &Plan, bar: &ProgressBar) -> Result<Row> {
    bar.set_message("W2 bspline7 drag");
    let dragged = PointRef::Control(w.curve, 3);
    let start = base.point(dragged)?;
    let (mut times, mut valid, mut failed) = (Vec::new(), 0, 0);
    for _ in 0..plan.w1_runs {
        let mut session = base.drag(dragged)?;
        for k in 1..=200_u32 {
            let dy = 0.0002 * f64::from(k.min(200 - k));
            let target = Point2::new(start.x, start.y + dy);
            let t0 = Instant::now();
            let outcome = session.update(target).map(|_| ());
            times.push(t0.elapsed());
            bar.inc(1);
            failed += usize::from(outcome.is_err());
            let held = session.residuals()?.iter().all(|(_, r)| *r <= TOL);
            valid += usize::from(outcome.is_ok() && held);
        }
    }
    let mut r = row(
        Workload::W2,
        "bspline7 drag update".to_owned(),
        &times,
        valid,
    );
    r.failed = failed;
    r.timer_s = Some(timer_overhead());
    Ok(r)
}

/// W3 (`affine` false) or W3a (true) for every chain size: one full solve timed per repeat,
/// each from the unsolved chain, with the growth exponent of the median between sizes.
pub(super) fn chains(plan: &Plan, affine: bool, bar: &ProgressBar) -> Result<Vec<Row>> {
    let workload = if affine { Workload::W3a } else { Workload::W3 };
    let mut rows: Vec<Row> = Vec::new();
    for &n in &plan.chain_sizes {
        bar.set_message(format!("{} N={n}", workload.name()));
        let (chain, segs) = if affine {
            wl::w3a_chain(n)?
        } else {
            wl::w3_chain(n)?
        };
        let (mut times, mut valid, mut failed) = (Vec::<Duration>::new(), 0, 0);
        let mut solvers = BTreeMap::new();
        for _ in 0..plan.chain_repeats(n) {
            let mut s = chain.clone();
            let t0 = Instant::now();
            let outcome = s.solve();
            times.push(t0.elapsed());
            bar.inc(1);
            match outcome {
                Ok(report) => count_solvers(&mut solvers, &report),
                Err(_) => failed += 1,
            }
            let ok = if affine {
                // WORKLOADS.md: every joint row within 1e-9, the pins exact.
                wl::w3a_valid(&s, &segs, 1e-9)
            } else {
                wl::w3_valid(&s, &segs, TOL)
            };
            valid += usize::from(ok);
        }
        let mut r = row(workload, format!("N={n}"), &times, valid);
        r.size = Some(n);
        r.failed = failed;
        r.solvers = solvers;
        if let Some(prev) = rows.last() {
            if let Some(m) = prev.size {
                set_growth(&mut r, m, prev.median_s);
            }
        }
        rows.push(r);
    }
    Ok(rows)
}

/// W4: `plan.w4_components` independent cubics in one sketch, the whole sketch solved
/// `plan.w4_repeats` times from the unsolved state.
pub(super) fn w4(plan: &Plan, bar: &ProgressBar) -> Result<Row> {
    let n = plan.w4_components;
    bar.set_message(format!("W4 {n} components"));
    let (sketch, curves) = wl::w4(n)?;
    let (mut times, mut valid, mut failed) = (Vec::new(), 0, 0);
    let mut solvers = BTreeMap::new();
    for _ in 0..plan.w4_repeats {
        let mut s = sketch.clone();
        let t0 = Instant::now();
        let outcome = s.solve();
        times.push(t0.elapsed());
        bar.inc(1);
        match outcome {
            Ok(report) => count_solvers(&mut solvers, &report),
            Err(_) => failed += 1,
        }
        valid += usize::from(wl::w4_valid(&s, &curves, TOL));
    }
    let mut r = row(Workload::W4, format!("{n} components"), &times, valid);
    r.size = Some(n);
    r.failed = failed;
    r.solvers = solvers;
    Ok(r)
}

/// W5 (`ladder` false) or W5b (true) for every size: one full solve timed per repeat, each
/// from the perturbed start, with the growth exponent of the median between sizes.
pub(super) fn rectangles(plan: &Plan, ladder: bool, bar: &ProgressBar) -> Result<Vec<Row>> {
    let workload = if ladder { Workload::W5b } else { Workload::W5 };
    sized_solves(plan, workload, bar, |n| {
        let (sketch, layout) = if ladder { wl::w5b(n)? } else { wl::w5(n)? };
        Ok((
            sketch,
            Box::new(move |s: &Sketch| wl::w5_valid(s, &layout, TOL)),
        ))
    })
}

/// W5r for every size, as W5: N rounded rectangles, one full solve timed per repeat from the
/// perturbed start, judged by [`wl::w5r_valid`].
pub(super) fn rounded_rectangles(plan: &Plan, bar: &ProgressBar) -> Result<Vec<Row>> {
    sized_solves(plan, Workload::W5r, bar, |n| {
        let (sketch, layout) = wl::w5r(n)?;
        Ok((
            sketch,
            Box::new(move |s: &Sketch| wl::w5r_valid(s, &layout, TOL)),
        ))
    })
}

/// A sketch to solve and its validity check.
type Judged = (Sketch, Box<dyn Fn(&Sketch) -> bool>);

/// For every size N of the plan: the sketch `build(N)` solved from its start
/// `plan.chain_repeats(N)` times (each solve timed on its own, each result judged by the
/// check), with the growth exponent of the median between sizes.
fn sized_solves(
    plan: &Plan,
    workload: Workload,
    bar: &ProgressBar,
    build: impl Fn(usize) -> camber_sketch::Result<Judged>,
) -> Result<Vec<Row>> {
    let mut rows: Vec<Row> = Vec::new();
    for &n in &plan.chain_sizes {
        bar.set_message(format!("{} N={n}", workload.name()));
        let (sketch, is_valid) = build(n)?;
        let (mut times, mut valid, mut failed) = (Vec::<Duration>::new(), 0, 0);
        let mut solvers = BTreeMap::new();
        for _ in 0..plan.chain_repeats(n) {
            let mut s = sketch.clone();
            let t0 = Instant::now();
            let outcome = s.solve();
            times.push(t0.elapsed());
            bar.inc(1);
            match outcome {
                Ok(report) => count_solvers(&mut solvers, &report),
                Err(_) => failed += 1,
            }
            valid += usize::from(is_valid(&s));
        }
        let mut r = row(workload, format!("N={n}"), &times, valid);
        r.size = Some(n);
        r.failed = failed;
        r.solvers = solvers;
        if let Some(prev) = rows.last() {
            if let Some(m) = prev.size {
                set_growth(&mut r, m, prev.median_s);
            }
        }
        rows.push(r);
    }
    Ok(rows)
}

/// W6: `plan.w6_rectangles` W5 rectangles solved once (untimed); then for k = 0, 1, 2, …
/// (cycling through the rectangles) rectangle k's width |bottom| = w(k) is set to w(k) + 0.05
/// and the sketch re-solved, the edit and the re-solve timed together. Valid: every constraint
/// of the whole sketch within 1e-6 (the edited width at its new value) and every entity of the
/// other rectangles bit for bit unchanged.
pub(super) fn w6(plan: &Plan, bar: &ProgressBar) -> Result<Row> {
    let n = plan.w6_rectangles;
    bar.set_message(format!("W6 {n} rectangles"));
    let (mut s, mut layout) = wl::w5(n)?;
    s.solve()?;
    let (mut times, mut valid, mut failed) = (Vec::new(), 0, 0);
    let mut solvers = BTreeMap::new();
    for edit in 0..plan.w6_edits {
        let k = edit % n;
        let bottom = layout.lines[4 * k];
        let width = s
            .constraints()
            .find_map(|(id, c)| match c {
                camber_sketch::Constraint::Distance(d) if d.a == PointRef::Start(bottom) => {
                    Some((id, d.distance))
                }
                _ => None,
            })
            .ok_or_else(|| anyhow!("W6: rectangle {k} has no width constraint"))?;
        let value = width.1 + 0.05;
        let before: Vec<(camber_sketch::EntityId, camber_sketch::Entity)> = s
            .entities()
            .filter(|(id, _)| !layout.lines[4 * k..4 * k + 4].contains(id))
            .map(|(id, e)| (id, e.clone()))
            .collect();
        let t0 = Instant::now();
        let outcome = s.set_value(width.0, value).and_then(|()| s.solve());
        times.push(t0.elapsed());
        bar.inc(1);
        match outcome {
            Ok(report) => count_solvers(&mut solvers, &report),
            Err(_) => failed += 1,
        }
        for slot in layout.lengths.iter_mut().filter(|(l, _)| *l == bottom) {
            slot.1 = value;
        }
        let others_kept = before
            .iter()
            .all(|(id, e)| s.entity(*id).is_ok_and(|now| now == e));
        valid += usize::from(others_kept && wl::w5_valid(&s, &layout, TOL));
    }
    let mut r = row(Workload::W6, format!("N={n} width edit"), &times, valid);
    r.size = Some(n);
    r.failed = failed;
    r.solvers = solvers;
    Ok(r)
}

/// W7: for each chain length N of `plan.w7_sizes`, the W3 chain solved once (untimed), then a
/// drag session on control point 1 of segment ⌊N/2⌋ along 200 targets on a circle of radius
/// 0.05 about its start (angle 2πk/200), each update timed. Valid: after the update every
/// constraint within 1e-6 and the point at its target.
pub(super) fn w7(plan: &Plan, bar: &ProgressBar) -> Result<Vec<Row>> {
    let mut rows = Vec::new();
    for &n in &plan.w7_sizes {
        bar.set_message(format!("W7 N={n}"));
        let (mut s, segs) = wl::w3_chain(n)?;
        s.solve()?;
        let dragged = PointRef::Control(segs[n / 2], 1);
        let start = s.point(dragged)?;
        let mut session = s.drag(dragged)?;
        let (mut times, mut valid, mut failed) = (Vec::new(), 0, 0);
        for k in 0..200_u32 {
            let th = std::f64::consts::TAU * f64::from(k) / 200.0;
            let target = start + 0.05 * nalgebra::Vector2::new(th.cos(), th.sin());
            let t0 = Instant::now();
            let outcome = session.update(target).map(|_| ());
            times.push(t0.elapsed());
            bar.inc(1);
            failed += usize::from(outcome.is_err());
            let held = session.residuals()?.iter().all(|(_, r)| *r <= TOL);
            let at = (session.point(dragged)? - target).norm() <= TOL;
            valid += usize::from(outcome.is_ok() && held && at);
        }
        let mut r = row(Workload::W7, format!("N={n} drag update"), &times, valid);
        r.size = Some(n);
        r.failed = failed;
        r.timer_s = Some(timer_overhead());
        rows.push(r);
    }
    Ok(rows)
}

/// W8: `plan.w8_variants` variants of the W2 `bspline7` sketch at its rough start, the circle
/// radii scaled by the W5 LCG's factors, all solved by one [`camber_sketch::solve_many`] call
/// on the current pool (one thread under `RAYON_NUM_THREADS=1`); each of `plan.w8_runs`
/// batches gives one time, its total / variants (the median and p95 are over the batches).
/// Valid: W2's check against each variant's own circles, counted over every variant of every
/// batch (the row's samples).
pub(super) fn w8(plan: &Plan, bar: &ProgressBar) -> Result<Row> {
    let n = plan.w8_variants;
    bar.set_message(format!("W8 {n} variants"));
    let (variants, w) = wl::w8_variants(n)?;
    let (starts, circles): (Vec<Sketch>, Vec<_>) = variants.into_iter().unzip();
    let (mut times, mut valid, mut failed) = (Vec::new(), 0, 0);
    let mut solvers = BTreeMap::new();
    for _ in 0..plan.w8_runs {
        let mut batch = starts.clone();
        let t0 = Instant::now();
        let results = camber_sketch::solve_many(&mut batch);
        let total = t0.elapsed();
        times.push(total / u32::try_from(n.max(1)).unwrap_or(u32::MAX));
        bar.inc(n as u64);
        for ((s, c), result) in batch.iter().zip(&circles).zip(&results) {
            match result {
                Ok(report) => count_solvers(&mut solvers, report),
                Err(_) => failed += 1,
            }
            valid += usize::from(wl::w2_valid_with(s, &w, c));
        }
    }
    let mut r = row(
        Workload::W8,
        format!("{n} bspline7 variants"),
        &times,
        valid,
    );
    // Every variant solved counts as a sample of the validity check; the times are one per
    // batch.
    r.samples = n * plan.w8_runs;
    r.size = Some(n);
    r.failed = failed;
    r.solvers = solvers;
    Ok(r)
}

/// Whether the analysis of the W3 chain of `n` segments is right. Its 8n unknowns lose 4 to the
/// pinned ends and 2(n − 1) to the merged joints, leaving 6n − 2; the rows are the n − 1 joint
/// directions and the n chords, all independent: DOF 4n − 1 in one component, nothing
/// redundant or conflicting.
fn w3_analysis_valid(analyses: &[camber_sketch::ComponentAnalysis], n: usize) -> bool {
    match analyses {
        [a] => {
            let d = &a.analysis;
            d.free_unknowns == 6 * n - 2
                && d.dof == 4 * n - 1
                && d.redundant.is_empty()
                && d.partly_redundant.is_empty()
                && d.conflicting.is_empty()
        }
        _ => false,
    }
}

/// Whether the analysis of the W5b ladder of `n` cells is right: one component, fully
/// constrained (DOF 0, nothing redundant, partly redundant or conflicting, no entity with
/// anything free), and settled by its blocks: no unknown needed the free-unknown projection.
fn ladder_analysis_valid(analyses: &[camber_sketch::ComponentAnalysis]) -> bool {
    match analyses {
        [a] => {
            let d = &a.analysis;
            d.dof == 0
                && d.rank == d.free_unknowns
                && d.redundant.is_empty()
                && d.partly_redundant.is_empty()
                && d.conflicting.is_empty()
                && a.freedom.is_empty()
                && d.structure.projected_unknowns == 0
        }
        _ => false,
    }
}

/// The sketches of workload A.
#[derive(Clone, Copy)]
enum Analysed {
    /// The W3 chain of N segments.
    W3,
    /// The chain of 10·N points held by distances.
    Points,
    /// The W5b ladder of N cells, fully constrained, from its perturbed start.
    Ladder,
    /// 10·N free points: 10·N components of one point.
    Free,
}

/// A: the DOF analysis (`Sketch::analyze`, as `camber check` runs it) of the W3 chain of N
/// segments, of the chain of 10·N points held by distances, of the W5b ladder of N cells and
/// of 10·N free points (as many components), one analysis timed per repeat, each checked
/// against the DOF its construction gives ([`w3_analysis_valid`],
/// `camber_workloads::point_chain_valid`, [`ladder_analysis_valid`],
/// `camber_workloads::free_points_valid`), with the growth exponent between sizes.
pub(super) fn analysis(plan: &Plan, bar: &ProgressBar) -> Result<Vec<Row>> {
    let mut rows: Vec<Row> = Vec::new();
    for (label, sketch_kind) in [
        ("W3", Analysed::W3),
        ("points", Analysed::Points),
        ("ladder", Analysed::Ladder),
        ("free points", Analysed::Free),
    ] {
        let mut last: Option<(usize, f64)> = None;
        for &n in &plan.chain_sizes {
            let size = match sketch_kind {
                Analysed::Points | Analysed::Free => 10 * n,
                Analysed::W3 | Analysed::Ladder => n,
            };
            bar.set_message(format!("A {label} N={size}"));
            let sketch = match sketch_kind {
                Analysed::W3 => wl::w3_chain(n)?.0,
                Analysed::Points => wl::point_chain(size)?,
                Analysed::Ladder => wl::w5b(n)?.0,
                Analysed::Free => wl::free_points(size)?,
            };
            let (mut times, mut valid, mut failed) = (Vec::<Duration>::new(), 0, 0);
            for _ in 0..plan.chain_repeats(n) {
                let t0 = Instant::now();
                let outcome = sketch.analyze();
                times.push(t0.elapsed());
                bar.inc(1);
                match outcome {
                    Ok(analyses) => {
                        let ok = match sketch_kind {
                            Analysed::W3 => w3_analysis_valid(&analyses, n),
                            Analysed::Points => wl::point_chain_valid(&analyses, size),
                            Analysed::Ladder => ladder_analysis_valid(&analyses),
                            Analysed::Free => wl::free_points_valid(&analyses, size),
                        };
                        valid += usize::from(ok);
                    }
                    Err(_) => failed += 1,
                }
            }
            let mut r = row(Workload::A, format!("{label} N={size}"), &times, valid);
            r.size = Some(size);
            r.failed = failed;
            if let Some((m, t)) = last {
                set_growth(&mut r, m, t);
            }
            last = Some((size, r.median_s));
            rows.push(r);
        }
    }
    Ok(rows)
}
