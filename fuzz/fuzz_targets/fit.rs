//! A point file (JSON, two columns, a Selig or Lednicer airfoil file) parsed and fitted to a
//! tolerance, whole and split at the leading edge, under a small work budget. The work is
//! camber_cli::fuzz_support::fit, which the corpus replay test also runs.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| camber_cli::fuzz_support::fit(data));
