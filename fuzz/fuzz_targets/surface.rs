//! A surface case: G1 deformation of the face, report and plot.
//! The work is camber_cli::fuzz_support::surface, which the corpus replay test also runs.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| camber_cli::fuzz_support::surface(data));
