//! DXF bytes (text or binary) imported as a sketch, saved and loaded as a sketch file,
//! exported as DXF and imported again. The work is camber_cli::fuzz_support::dxf, which the
//! corpus replay test also runs.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| camber_cli::fuzz_support::dxf(data));
