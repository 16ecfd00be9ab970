//! Hostile texts: sizes and nesting refused before work, long flat texts compiled without deep
//! recursion, on a thread with a small stack.

use camber_expr::{compile, Error, Names, MAX_DEPTH, MAX_EXPRESSION_BYTES};

fn names() -> Names {
    Names::new().with_scalar("s", 0, 0).with_vector("p", 1)
}

/// Runs `f` on a thread with a 256 KiB stack (much less than a rayon worker's).
fn small_stack<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
    std::thread::Builder::new()
        .stack_size(256 * 1024)
        .spawn(f)
        .and_then(|h| {
            h.join()
                .map_err(|_| std::io::Error::other("the thread panicked"))
        })
        .unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn a_megabyte_expression_is_refused_before_it_is_read() {
    let text = "s+".repeat(500_000) + "s";
    let e = compile(&[text.as_str()], &mut names()).map(|_| ());
    assert_eq!(
        e,
        Err(Error::TooLong {
            bytes: 1_000_001,
            max: MAX_EXPRESSION_BYTES
        })
    );
}

#[test]
fn deep_nesting_is_refused_with_the_column_of_the_first_bracket_too_many() {
    for open in ["(", "[", "sin(", "norm(["] {
        let text = open.repeat(10_000) + "s";
        let e = small_stack(move || compile(&[text.as_str()], &mut names()).map(|_| ()));
        match e {
            Err(Error::TooDeep { column, max }) => {
                assert_eq!(max, MAX_DEPTH);
                assert!(column > MAX_DEPTH && column <= (MAX_DEPTH + 1) * open.len());
            }
            other => panic!("{open}: {other:?}"),
        }
    }
    // Exactly at the limit it compiles.
    let ok = "(".repeat(MAX_DEPTH) + "s" + &")".repeat(MAX_DEPTH);
    assert!(compile(&[ok.as_str()], &mut names()).is_ok());
}

#[test]
fn long_flat_texts_compile_on_a_small_stack() {
    let limit = MAX_EXPRESSION_BYTES - 8;
    let texts = [
        "s+".repeat(limit / 2) + "s",
        "s*".repeat(limit / 2) + "s",
        "-".repeat(limit) + "s",
        "s^".repeat(limit / 2) + "s",
        "2^".repeat(limit / 2) + "1",
        "p.x+".repeat(limit / 4) + "s",
        "(s)+".repeat(limit / 4) + "s",
    ];
    for text in texts {
        let head: String = text.chars().take(6).collect();
        let r = small_stack(move || compile(&[text.as_str()], &mut names()).map(|p| p.rows()));
        assert!(
            r.is_ok() || matches!(r, Err(Error::NonFinite { .. })),
            "{head}…: {r:?}"
        );
    }
}

#[test]
fn garbage_bytes_give_errors_not_panics() {
    let texts = [
        "\u{0}",
        "((((",
        "))))",
        "]]",
        "[,]",
        "1..2",
        "1e",
        "1e+",
        ".",
        "..5",
        "s.",
        "p.",
        "p..x",
        "'",
        "s''(1)",
        "C(",
        "C(1,",
        "sin()",
        "sin(,)",
        "+",
        "-",
        "^",
        "**",
        "s ^",
        "1 ** ** 2",
        "[1, 2, 3]",
        "[1]",
        "vec(1)",
        "=",
        "1 =",
        "= 1",
        "\u{feff}s",
        "s\n+\n1",
        "s\t*\t2",
        "1_000",
        "_",
        "__x",
        "0x10",
        "1e-400",
        "NaN",
        "inf",
        "infinity",
    ];
    for text in texts {
        let r = compile(&[text], &mut names());
        if let Err(e) = &r {
            // Every error but the size ones has a column inside (or just past) the text.
            if let Some(c) = e.column() {
                assert!(c >= 1 && c <= text.chars().count() + 1, "{text:?}: {e}");
            }
        }
    }
    // NaN and inf are names like any other: unknown here.
    assert!(matches!(
        compile(&["NaN"], &mut names()),
        Err(Error::UnknownName { .. })
    ));
    // A denormal underflow is a finite number.
    assert!(compile(&["1e-400 + s"], &mut names()).is_ok());
}
