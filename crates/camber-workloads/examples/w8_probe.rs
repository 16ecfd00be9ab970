//! W8 probe for profiling (`valgrind --tool=callgrind`): solves the first n W8 variants one
//! after another, by `solve_all` per sketch ("each") or by one `camber_sketch::solve_many`
//! call ("many"), and prints the time per variant and the valid count.
//!
//! `RAYON_NUM_THREADS=1 target/release/examples/w8_probe 10000 many`

fn main() -> Result<(), camber_sketch::Error> {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(1000);
    let mode = args.get(2).cloned().unwrap_or_else(|| "many".to_owned());
    let (variants, w) = camber_workloads::w8_variants(n)?;
    let (mut sketches, circles): (Vec<_>, Vec<_>) = variants.into_iter().unzip();
    let t0 = std::time::Instant::now();
    let failed: usize = if mode == "each" {
        sketches
            .iter_mut()
            .map(|s| usize::from(s.solve_all().is_err()))
            .sum()
    } else {
        camber_sketch::solve_many(&mut sketches)
            .iter()
            .map(|r| usize::from(r.is_err()))
            .sum()
    };
    let dt = t0.elapsed();
    let valid = sketches
        .iter()
        .zip(&circles)
        .filter(|(s, c)| camber_workloads::w2_valid_with(s, &w, c))
        .count();
    println!(
        "{mode}: {:.2} us/variant, {valid}/{n} valid, {failed} failed",
        dt.as_secs_f64() * 1e6 / n as f64
    );
    Ok(())
}
