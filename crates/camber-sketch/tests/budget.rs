//! The evaluation budget of a sketch solve (`NonlinearOptions::max_evaluations`): one budget
//! shared by the given start, its active-set rounds and every other contact start, so that a
//! sketch that cannot be solved fails in bounded work, honestly and without changing the
//! sketch.

#![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

use camber_sketch::file::{from_json, to_json};

/// A fuzzer's find: a B-spline with a C1 join, contacts at free parameters, an arc length and
/// a curvature that no start satisfies. Before the budget every contact start ran every
/// failing path in turn (5.3 s in release).
const UNSOLVABLE: &str =
    include_str!("../../../fuzz/corpus/sketch/slow_failing_solve_arc_length_contacts.json");

fn with_budget(text: &str, evaluations: Option<usize>) -> camber_sketch::Sketch {
    let mut s = from_json(text).unwrap();
    let mut options = s.options().clone();
    options.nonlinear = options.nonlinear.with_max_evaluations(evaluations);
    s.set_options(options);
    s
}

#[test]
fn a_spent_budget_ends_the_solve_unchanged_and_says_so() {
    let mut s = with_budget(UNSOLVABLE, Some(40));
    let before = to_json(&s).unwrap();
    let err = s.solve().unwrap_err();
    let text = err.to_string();
    assert!(text.contains("not solved"), "{text}");
    assert!(text.contains("budget of 40 evaluations is spent"), "{text}");
    assert_eq!(
        to_json(&s).unwrap(),
        before,
        "a failed solve changed the sketch"
    );
}

#[test]
fn a_budget_does_not_change_a_solve_it_suffices_for() {
    // The bundled diffuser (contacts with circles) solves well within the default budget; a budget that barely
    // suffices gives the same answer as none.
    let text = include_str!("../../../examples/sketches/diffuser.json");
    let mut unlimited = with_budget(text, None);
    let mut limited = with_budget(text, Some(camber_solve::DEFAULT_MAX_EVALUATIONS));
    unlimited.solve().unwrap();
    limited.solve().unwrap();
    assert_eq!(to_json(&unlimited).unwrap(), to_json(&limited).unwrap());
}

#[test]
fn a_raised_cancel_flag_stops_the_solve_unchanged_and_says_so() {
    // No evaluation limit: only the flag, raised by another thread while the solve runs (as
    // the Python package does on Ctrl-C), can end this solve early.
    let mut s = with_budget(UNSOLVABLE, None);
    let flag = camber_solve::CancelFlag::new();
    s.set_options(s.options().clone().with_cancel(Some(flag.clone())));
    let before = to_json(&s).unwrap();
    let raiser = {
        let flag = flag.clone();
        std::thread::spawn(move || {
            std::thread::sleep(std::time::Duration::from_millis(20));
            flag.cancel();
        })
    };
    let err = s.solve().unwrap_err();
    raiser.join().unwrap();
    assert!(
        matches!(
            err,
            camber_sketch::Error::Solve(camber_solve::Error::Cancelled)
        ),
        "{err}"
    );
    assert_eq!(
        to_json(&s).unwrap(),
        before,
        "a cancelled solve changed the sketch"
    );
    // A flag raised before the solve stops it at its first evaluation.
    let err = s.solve().unwrap_err();
    assert!(err.to_string().contains("cancelled"), "{err}");
}
