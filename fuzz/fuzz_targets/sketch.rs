//! Sketch file bytes: load, check (DOF analysis, warnings), render, solve.
//! The work is camber_cli::fuzz_support::sketch, which the corpus replay test also runs.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| camber_cli::fuzz_support::sketch(data));
