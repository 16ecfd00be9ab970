//! W3, the nonlinear G1 chain with chord lengths: a solved chain passes the workload's own
//! validity check, and the unsolved one does not.

use camber_workloads::{w3_chain, w3_valid};

#[test]
fn w3_chain_solves_to_a_valid_chain() -> Result<(), camber_sketch::Error> {
    for n in [2, 10, 100] {
        let (mut s, segs) = w3_chain(n)?;
        assert!(!w3_valid(&s, &segs, 1e-6), "n = {n}: valid before solving");
        s.solve()?;
        assert!(w3_valid(&s, &segs, 1e-6), "n = {n}: invalid after solving");
    }
    Ok(())
}

/// One segment cannot keep its chord when its far end moves off the chord circle: the solver
/// must say so and leave the sketch as it was.
#[test]
fn a_single_segment_is_conflicting() -> Result<(), camber_sketch::Error> {
    let (mut s, segs) = w3_chain(1)?;
    let before = s.point(camber_sketch::PointRef::Control(segs[0], 1))?;
    assert!(matches!(
        s.solve(),
        Err(camber_sketch::Error::Conflicting { .. })
    ));
    assert_eq!(
        s.point(camber_sketch::PointRef::Control(segs[0], 1))?,
        before
    );
    Ok(())
}
