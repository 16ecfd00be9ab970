//! Long calls that Ctrl-C can stop: [`run`].
//!
//! A call that loops or solves releases the GIL, so Python's own signal handling cannot run
//! while it works. [`run`] moves the work onto a scoped thread and keeps the calling thread
//! (the main thread, where CPython delivers signals) waiting in slices of [`POLL`]: after each
//! slice it takes the GIL for an instant and calls `PyErr_CheckSignals`. When a handler raises
//! (Ctrl-C: `KeyboardInterrupt`), it raises the work's [`CancelFlag`] and waits for the work to
//! return. The work hands the flag to what it calls: a solve through
//! [`camber_solve::Options::cancel`] (every evaluation charged to the budget reads it), the
//! curve toolkit through its budget's stop flag (`camber_geom::Budget::with_stop`), a batch
//! between its items. The handler's exception is then raised, whatever the work returned.
//!
//! Work that ends before it reads the flag keeps its effect (a solve that finished is written
//! back); work stopped by the flag fails the way every failed call does, leaving its objects as
//! they were. The delay between Ctrl-C and the exception is one poll slice plus the time to the
//! work's next look at the flag (an evaluation, a quadrature step): well under a second.

use std::sync::mpsc;
use std::time::Duration;

use camber_solve::CancelFlag;
use pyo3::prelude::*;

/// How long the waiting thread sleeps between two looks at Python's signals.
pub const POLL: Duration = Duration::from_millis(50);

/// Runs `work` with the GIL released on a scoped thread, honouring Ctrl-C (see the module
/// documentation). `work` gets the flag to pass on to what it calls.
///
/// # Errors
/// The exception a signal handler raised while the work ran (`KeyboardInterrupt` for
/// Ctrl-C); the work's own result is dropped then.
pub fn run<T, F>(py: Python<'_>, work: F) -> PyResult<T>
where
    T: Send,
    F: FnOnce(&CancelFlag) -> T + Send,
{
    let flag = CancelFlag::new();
    let (result, raised) = py.detach(|| wait_for(&flag, work));
    match (raised, result) {
        (Some(err), _) => Err(err),
        (None, Ok(result)) => Ok(result),
        (None, Err(e)) => Err(crate::errors::CamberError::new_err(format!(
            "cannot start the work thread: {e}"
        ))),
    }
}

/// [`run`] for the curve toolkit: `work` gets a [`camber_geom::Budget`] whose stop flag is the
/// call's cancel flag (so Ctrl-C stops a quadrature, a fit or an intersection at its next
/// charge), and a library error becomes a `GeometryError` with the library's message.
///
/// # Errors
/// The signal handler's exception (see [`run`]), else the work's error as a `GeometryError`.
pub fn run_geometry<T, F>(py: Python<'_>, work: F) -> PyResult<T>
where
    T: Send,
    F: FnOnce(&camber_geom::Budget) -> camber_geom::Result<T> + Send,
{
    run(py, |flag| {
        work(&camber_geom::Budget::default().with_stop(flag.as_arc().clone()))
    })?
    .map_err(crate::errors::geometry)
}

/// The waiting half of [`run`], without the GIL: the work's result (or why its thread could not
/// start) and the exception a signal handler raised meanwhile (the first one).
fn wait_for<T, F>(flag: &CancelFlag, work: F) -> (std::io::Result<T>, Option<PyErr>)
where
    T: Send,
    F: FnOnce(&CancelFlag) -> T + Send,
{
    let (tx, rx) = mpsc::channel::<()>();
    let mut raised: Option<PyErr> = None;
    let result = std::thread::scope(|scope| {
        let worker = std::thread::Builder::new()
            .name("camber-work".into())
            .spawn_scoped(scope, move || {
                // The sender drops when the work returns or panics: the waiting loop wakes.
                let _done = tx;
                work(flag)
            })?;
        // Wakes when the sender drops (the work returned or panicked), or after each slice.
        while let Err(mpsc::RecvTimeoutError::Timeout) = rx.recv_timeout(POLL) {
            if raised.is_none() {
                if let Err(e) = Python::attach(|py| py.check_signals()) {
                    raised = Some(e);
                    flag.cancel();
                }
            }
        }
        match worker.join() {
            Ok(r) => Ok(r),
            Err(panic) => std::panic::resume_unwind(panic),
        }
    });
    (result, raised)
}
