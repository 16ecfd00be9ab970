//! Sweep probe: solves `n` variants of a parametric sketch file through
//! `camber_sketch::parameters::sweep::solve_variants` on one worker (the path of Python's
//! `solve_many(sketch, parameters=…)` and `camber batch --parameters`), parameter `name`
//! taking values spread ±2 % around its own, and prints the time per variant and how many
//! solved.
//!
//! `target/release/examples/sweep_probe examples/sketches/diffuser_parametric.json r3 2000`

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let path = args.get(1).ok_or("usage: sweep_probe FILE PARAMETER [N]")?;
    let name = args.get(2).ok_or("usage: sweep_probe FILE PARAMETER [N]")?;
    let n: usize = args.get(3).and_then(|a| a.parse().ok()).unwrap_or(1000);
    let base = camber_sketch::file::from_json(&std::fs::read_to_string(path)?)?;
    let v0 = base.parameter(name).ok_or("no such parameter")?;
    let column: Vec<f64> = (0..n)
        .map(|i| v0 * (0.98 + 0.04 * i as f64 / n.max(1) as f64))
        .collect();
    let table = camber_sketch::parameters::sweep::Table::try_new(vec![(name.clone(), column)])?;
    let t0 = std::time::Instant::now();
    let rows = camber_sketch::parameters::sweep::solve_variants(&base, &table, Some(1))?;
    let dt = t0.elapsed();
    let ok = rows.iter().filter(|r| r.ok).count();
    println!(
        "{n} variants of {path} ({name}): {:.1} µs per variant, {ok} solved",
        dt.as_secs_f64() * 1e6 / n as f64
    );
    Ok(())
}
