//! Rough phase timings of the large workloads (development aid).
use camber_sketch::workloads::{w3a_chain, w4};
use std::time::Instant;

fn main() -> Result<(), camber_sketch::Error> {
    let (s, segs) = w3a_chain(10_000)?;
    let t = Instant::now();
    let comps = s.components();
    println!("components {:?}", t.elapsed());
    let t = Instant::now();
    let cp = s.component_problem(segs[0])?;
    println!("components+build {:?}", t.elapsed());
    let t = Instant::now();
    let lin = cp
        .problem()
        .linearize()
        .map_err(camber_sketch::Error::from)?;
    println!(
        "linearize {:?} ({} x {})",
        t.elapsed(),
        lin.g.len(),
        lin.map.len()
    );
    let t = Instant::now();
    let f = camber_solve::MinNormFactorization::try_sparse(&lin.jacobian, lin.map.weights());
    println!("factorize {:?} {}", t.elapsed(), f.is_ok());
    let mut s2 = s.clone();
    let t = Instant::now();
    s2.solve()?;
    println!("solve {:?} {}", t.elapsed(), comps.len());
    let (s, _) = w4(10_000)?;
    let mut s3 = s.clone();
    let t = Instant::now();
    let _ = s3.components();
    println!("w4 components {:?}", t.elapsed());
    let t = Instant::now();
    s3.solve()?;
    println!("w4 solve {:?}", t.elapsed());
    Ok(())
}
