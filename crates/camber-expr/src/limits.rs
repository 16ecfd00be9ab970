//! The bounds every expression is checked against before any work is done on it.
//!
//! A row longer than [`MAX_EXPRESSION_BYTES`] is refused without being read; brackets nested
//! deeper than [`MAX_DEPTH`] are found by one linear scan before parsing, so the parser's
//! recursion (brackets only: sums, products, signs and powers are loops) stays shallow on any
//! thread. The compiled size is bounded by [`MAX_TAPE`] as it grows.

use crate::errors::{Error, Result};

/// The longest row text, in bytes (64 KiB).
pub const MAX_EXPRESSION_BYTES: usize = 64 * 1024;

/// The deepest nesting of brackets `( [` (calls included).
pub const MAX_DEPTH: usize = 64;

/// The most rows in one expression constraint (a vector row counts once here).
pub const MAX_ROWS: usize = 64;

/// The most operations and combination terms of one compiled expression (all rows).
pub const MAX_TAPE: usize = 1 << 18;

/// Checks a row's length and nesting before it is parsed.
pub(crate) fn prescan(text: &str) -> Result<()> {
    if text.len() > MAX_EXPRESSION_BYTES {
        return Err(Error::TooLong {
            bytes: text.len(),
            max: MAX_EXPRESSION_BYTES,
        });
    }
    let mut depth = 0usize;
    for (column, c) in text.chars().enumerate() {
        match c {
            '(' | '[' => {
                depth += 1;
                if depth > MAX_DEPTH {
                    return Err(Error::TooDeep {
                        column: column + 1,
                        max: MAX_DEPTH,
                    });
                }
            }
            ')' | ']' => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    Ok(())
}
