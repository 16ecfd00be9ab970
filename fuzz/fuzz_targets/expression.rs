//! Expression rows (one per line) compiled against a fixed sketch, evaluated, differentiated,
//! added and solved. The work is camber_cli::fuzz_support::expression, which the corpus replay
//! test also runs.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| camber_cli::fuzz_support::expression(data));
