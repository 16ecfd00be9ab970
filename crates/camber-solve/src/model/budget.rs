//! [`Budget`]: the evaluations a solve may still spend over every path, start and active-set
//! round it tries, so that a solve that fails does so in bounded time.
//!
//! Every path of the selection has its own limit (Newton and Levenberg–Marquardt iterations,
//! SLSQP evaluations), but a failing solve runs them all in turn, and a sketch runs that cascade
//! again from each contact start and in each active-set round. With expensive residuals (an
//! arc length is a quadrature over the curve) the product reached seconds. The budget counts
//! what all of them share: one unit per evaluation of the residuals, of their Jacobian or of a
//! Hessian, whatever path asks for it (SLSQP's own evaluations and every line-search trial
//! included: a budget of derivative evaluations alone let SLSQP's value evaluations run on). The count is deterministic (no clock), so a
//! solve that runs out does so at the same point on every machine.
//!
//! The budget also carries the caller's [`CancelFlag`] ([`crate::Options::cancel`]): once it is
//! raised, every charge is refused with [`Error::Cancelled`] and the budget reads as spent, so
//! every path and every start stops at its next evaluation.

use std::sync::atomic::{AtomicUsize, Ordering};

use crate::model::errors::{Error, Result};
use crate::model::options::CancelFlag;

/// A count of evaluations spent against an optional limit, kept inside a
/// [`crate::Problem`] ([`crate::Problem::start_budget`]).
///
/// An atomic counter, so that a problem stays `Sync`; a solve charges it from one thread.
#[derive(Debug)]
pub(crate) struct Budget {
    spent: AtomicUsize,
    /// The most evaluations allowed since the budget started; `usize::MAX` when none runs.
    limit: AtomicUsize,
    /// Whether a budget runs (started and not ended).
    running: std::sync::atomic::AtomicBool,
    /// The caller's flag: raised, it refuses every charge.
    cancel: Option<CancelFlag>,
}

impl Default for Budget {
    /// No budget running: evaluations are counted, never refused.
    fn default() -> Self {
        Self {
            spent: AtomicUsize::new(0),
            limit: AtomicUsize::new(usize::MAX),
            running: std::sync::atomic::AtomicBool::new(false),
            cancel: None,
        }
    }
}

impl Budget {
    /// Starts counting from zero with `limit` evaluations allowed (`None`: no limit, only the
    /// count).
    pub(crate) fn start(&self, limit: Option<usize>) {
        self.spent.store(0, Ordering::Relaxed);
        self.limit
            .store(limit.unwrap_or(usize::MAX), Ordering::Relaxed);
        self.running.store(true, Ordering::Relaxed);
    }

    /// Stops the budget: evaluations are counted but never refused until the next start.
    pub(crate) fn end(&self) {
        self.limit.store(usize::MAX, Ordering::Relaxed);
        self.running.store(false, Ordering::Relaxed);
    }

    /// Whether a budget runs.
    pub(crate) fn running(&self) -> bool {
        self.running.load(Ordering::Relaxed)
    }

    /// Evaluations spent since the budget started.
    pub(crate) fn spent(&self) -> usize {
        self.spent.load(Ordering::Relaxed)
    }

    /// The limit of the running budget, if any.
    pub(crate) fn limit(&self) -> Option<usize> {
        match self.limit.load(Ordering::Relaxed) {
            usize::MAX => None,
            n => Some(n),
        }
    }

    /// Watches `cancel` (none: nothing to watch) until it is replaced.
    pub(crate) fn set_cancel(&mut self, cancel: Option<CancelFlag>) {
        self.cancel = cancel;
    }

    /// Whether the caller raised the cancel flag.
    pub(crate) fn cancelled(&self) -> bool {
        self.cancel.as_ref().is_some_and(CancelFlag::is_cancelled)
    }

    /// Whether every allowed evaluation is spent (or the solve is cancelled).
    pub(crate) fn exhausted(&self) -> bool {
        self.spent() >= self.limit.load(Ordering::Relaxed) || self.cancelled()
    }

    /// Spends one evaluation.
    ///
    /// # Errors
    /// [`Error::Cancelled`] once the cancel flag is raised; [`Error::BudgetSpent`] when none is
    /// left (the evaluation must not run).
    pub(crate) fn charge(&self) -> Result<()> {
        if self.cancelled() {
            return Err(Error::Cancelled);
        }
        let limit = self.limit.load(Ordering::Relaxed);
        let spent = self.spent.load(Ordering::Relaxed);
        if spent >= limit {
            return Err(Error::BudgetSpent { evaluations: limit });
        }
        self.spent.store(spent + 1, Ordering::Relaxed);
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_budget_refuses_the_evaluation_after_its_last() {
        let b = Budget::default();
        assert!(b.charge().is_ok(), "no budget running: nothing is refused");
        b.start(Some(2));
        assert_eq!(b.spent(), 0);
        assert!(b.charge().is_ok() && b.charge().is_ok());
        assert!(b.exhausted());
        assert_eq!(b.charge(), Err(Error::BudgetSpent { evaluations: 2 }));
        assert_eq!(b.spent(), 2, "a refused evaluation is not counted");
        b.end();
        assert!(!b.running() && b.charge().is_ok());
    }

    #[test]
    fn a_raised_cancel_flag_refuses_every_charge() {
        let mut b = Budget::default();
        let flag = CancelFlag::new();
        b.set_cancel(Some(flag.clone()));
        b.start(None);
        assert!(b.charge().is_ok() && !b.exhausted());
        flag.cancel();
        assert_eq!(b.charge(), Err(Error::Cancelled));
        assert!(
            b.exhausted(),
            "a cancelled budget reads as spent, so loops stop"
        );
        b.set_cancel(None);
        assert!(b.charge().is_ok());
    }

    #[test]
    fn an_unlimited_budget_only_counts() {
        let b = Budget::default();
        b.start(None);
        for _ in 0..5 {
            b.charge().unwrap();
        }
        assert_eq!((b.spent(), b.limit(), b.exhausted()), (5, None, false));
    }
}
