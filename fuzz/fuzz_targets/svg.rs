//! SVG path data or a whole SVG document imported into a sketch. The work is
//! camber_cli::fuzz_support::svg, which the corpus replay test also runs.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| camber_cli::fuzz_support::svg(data));
