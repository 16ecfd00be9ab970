//! One or two curves and some numbers: every operation of the curve toolkit (arc length, the
//! arc-length map, parameters at lengths, closest point, knot removal, offset, fitting,
//! splits checked by eval, intersections with overlaps, distance) under a small work budget.
//! The work is camber_cli::fuzz_support::toolkit, which the corpus replay test also runs.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| camber_cli::fuzz_support::toolkit(data));
