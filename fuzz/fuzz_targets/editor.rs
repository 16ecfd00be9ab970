//! A script of requests to the editor's handler (method, path, body per line).
//! The work is camber_cli::fuzz_support::editor, which the corpus replay test also runs.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| camber_cli::fuzz_support::editor(data));
