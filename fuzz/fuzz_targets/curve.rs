//! Curve file bytes: load, evaluate, draw, and every `camber op`.
//! The work is camber_cli::fuzz_support::curve, which the corpus replay test also runs.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| camber_cli::fuzz_support::curve(data));
