//! The language against hand-computed values: precedence, vectors, functions, constants,
//! affinity, and errors that name the column of their cause.

use approx::assert_abs_diff_eq;
use camber_expr::{compile, Error, Names, Program};

fn names() -> Names {
    Names::new()
        .with_vector("p", 0)
        .with_vector("q", 1)
        .with_scalar("s", 2, 0)
        .with_scalar("t", 2, 1)
        .with_constant("k", 3.0)
}

/// p = (3, 4), q = (−1, 2), s = 0.5, t = −2.
fn x() -> Vec<Vec<f64>> {
    vec![vec![3.0, 4.0], vec![-1.0, 2.0], vec![0.5, -2.0]]
}

fn eval(program: &Program) -> Vec<f64> {
    let x = x();
    let refs: Vec<&[f64]> = x.iter().map(Vec::as_slice).collect();
    let mut out = vec![0.0; program.rows()];
    program.eval(&refs, &(), &mut out);
    out
}

fn value(text: &str) -> Vec<f64> {
    eval(&compile(&[text], &mut names()).unwrap_or_else(|e| panic!("{text}: {e}")))
}

fn error(text: &str) -> Error {
    match compile(&[text], &mut names()) {
        Ok(_) => panic!("{text} compiled"),
        Err(e) => e,
    }
}

#[test]
fn precedence_follows_the_usual_rules() {
    let cases: &[(&str, f64)] = &[
        ("1 + 2 * 3", 7.0),
        ("(1 + 2) * 3", 9.0),
        ("2 ^ 3 ^ 2", 512.0),
        ("2 ** 3", 8.0),
        ("-2 ^ 2", -4.0),
        ("2 ^ -1", 0.5),
        ("- - 3", 3.0),
        ("+3 - -2", 5.0),
        ("12 / 3 / 2", 2.0),
        ("10 - 4 - 3", 3.0),
        ("s * t + k", 2.0),
        ("k ^ 2 / 9", 1.0),
        ("1e2 + .5 + 2.", 102.5),
        ("-s ^ 2", -0.25),
        ("t ^ 3", -8.0),
        ("2 ^ s ^ 2", 2f64.powf(0.25)),
    ];
    for (text, want) in cases {
        assert_abs_diff_eq!(value(text)[0], *want, epsilon = 1e-14);
    }
}

#[test]
fn vectors_add_scale_and_split_into_two_rows() {
    assert_eq!(value("p + q"), vec![2.0, 6.0]);
    assert_eq!(value("p - q - [1, 0]"), vec![3.0, 2.0]);
    assert_eq!(value("2 * p"), vec![6.0, 8.0]);
    assert_eq!(value("p * 2 / 4"), vec![1.5, 2.0]);
    assert_eq!(value("-p"), vec![-3.0, -4.0]);
    assert_eq!(value("p.x * q.y"), vec![6.0]);
    assert_eq!(value("(p + q).y"), vec![6.0]);
    assert_eq!(value("vec(s, t)"), vec![0.5, -2.0]);
    assert_eq!(value("perp(p)"), vec![-4.0, 3.0]);
    assert_eq!(value("p = q"), vec![4.0, 2.0]);
}

#[test]
fn functions_match_their_definitions() {
    let (p, q) = ([3.0f64, 4.0], [-1.0f64, 2.0]);
    let cases: &[(&str, f64)] = &[
        ("dot(p, q)", p[0] * q[0] + p[1] * q[1]),
        ("cross(p, q)", p[0] * q[1] - p[1] * q[0]),
        ("norm(p)", 5.0),
        ("norm(unit(q))", 1.0),
        ("sqrt(k)", 3f64.sqrt()),
        ("sin(s) + cos(t)", 0.5f64.sin() + (-2f64).cos()),
        ("tan(s)", 0.5f64.tan()),
        (
            "asin(s) + acos(s) + atan(t)",
            0.5f64.asin() + 0.5f64.acos() + (-2f64).atan(),
        ),
        ("atan2(t, s)", (-2f64).atan2(0.5)),
        ("exp(s) * ln(k)", 0.5f64.exp() * 3f64.ln()),
        ("abs(t)", 2.0),
        ("hypot(s, t)", 0.5f64.hypot(-2.0)),
        (
            "angle(p, q)",
            (p[0] * q[1] - p[1] * q[0]).atan2(p[0] * q[0] + p[1] * q[1]),
        ),
        ("pi", std::f64::consts::PI),
        ("s ^ t", 0.5f64.powf(-2.0)),
        ("k ^ s", 3f64.powf(0.5)),
    ];
    for (text, want) in cases {
        assert_abs_diff_eq!(value(text)[0], *want, epsilon = 1e-14);
    }
}

#[test]
fn several_rows_stack_in_order() {
    let program = compile(&["s", "p", "t = 1"], &mut names()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(program.rows(), 4);
    assert_eq!(eval(&program), vec![0.5, 3.0, 4.0, -3.0]);
}

#[test]
fn affinity_is_read_from_the_tape() {
    let affine = [
        "p - q",
        "2 * p + k * q",
        "(p - q) / 2",
        "dot(p, [1, 2])",
        "cross(p - q, [0, 1])",
        "s - t * k ^ 2",
        "-(s + 1) = t",
        "sqrt(k) * s",
        "p.x",
    ];
    let nonlinear = [
        "s * t",
        "dot(p, q)",
        "norm(p)",
        "sin(s)",
        "s ^ 2",
        "1 / s",
        "k ^ s",
        "abs(s)",
    ];
    for text in affine {
        assert!(
            compile(&[text], &mut names()).is_ok_and(|p| p.is_affine()),
            "{text}"
        );
    }
    for text in nonlinear {
        assert!(
            compile(&[text], &mut names()).is_ok_and(|p| !p.is_affine()),
            "{text}"
        );
    }
    let mixed = compile(&["p - q", "s * t"], &mut names()).unwrap_or_else(|e| panic!("{e}"));
    assert!(!mixed.is_affine());
}

#[test]
fn constants_fold_and_registers_are_reused() {
    let folded =
        compile(&["s + (2 * 3 - sqrt(16)) * k"], &mut names()).unwrap_or_else(|e| panic!("{e}"));
    // s + 2·3 is one affine combination (s + 6): a single instruction.
    assert_eq!(folded.len(), 1);
    let long = ["s*t + ".repeat(200) + "s"];
    let rows: Vec<&str> = long.iter().map(String::as_str).collect();
    let program = compile(&rows, &mut names()).unwrap_or_else(|e| panic!("{e}"));
    assert!(
        program.registers() <= 4,
        "{} registers",
        program.registers()
    );
    assert_abs_diff_eq!(eval(&program)[0], -200.0 + 0.5, epsilon = 1e-12);
}

#[test]
fn affine_parts_fold_and_repeated_subexpressions_are_computed_once() {
    // p − q is two combinations (p.x − q.x, p.y − q.y); the second p − q is the first; the dot
    // product is two products and a sum: five instructions, as by hand.
    let program = compile(&["dot(p - q, p - q)"], &mut names()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(program.len(), 5);
    assert_abs_diff_eq!(eval(&program)[0], 16.0 + 4.0, epsilon = 1e-12);
    // A combination scaled, negated and shifted stays one: −(2·(p.x − q.x) + s)/4 + 1.
    let program = compile(&["-(2 * (p.x - q.x) + s) / 4 + 1"], &mut names())
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(program.len(), 1);
    assert!(program.is_affine());
    assert_abs_diff_eq!(
        eval(&program)[0],
        -(2.0 * 4.0 + 0.5) / 4.0 + 1.0,
        epsilon = 1e-12
    );
    // The same nonlinear node written twice is computed once: sin(s)·sin(s) + sin(s).
    let program =
        compile(&["sin(s) * sin(s) + sin(s)"], &mut names()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(program.len(), 4);
    let v = 0.5_f64.sin();
    assert_abs_diff_eq!(eval(&program)[0], v * v + v, epsilon = 1e-15);
    // x − x is the constant zero, whatever x is.
    let program = compile(&["(p.x - p.x) * s + 2"], &mut names()).unwrap_or_else(|e| panic!("{e}"));
    assert!(program.is_affine());
    assert_abs_diff_eq!(eval(&program)[0], 2.0, epsilon = 1e-15);
}

#[test]
fn syntax_errors_point_at_the_column() {
    let cases: &[(&str, usize, &str)] = &[
        ("1 +", 4, "column 4: expected an operand (a number, a name, `(` or `[`), found the end of the expression"),
        ("(s + 1", 7, "column 7: expected `)`, found the end of the expression"),
        ("s t", 3, "column 3: expected an operator or the end of the expression, found `t`"),
        ("2x", 2, "column 2: expected an operator or the end of the expression, found `x`"),
        ("s * * t", 5, "column 5: expected an operand (a number, a name, `(` or `[`), found `*`"),
        ("[s t]", 4, "column 4: expected `,`, found `t`"),
        ("dot", 4, "column 4: expected `(` after the function `dot`, found the end of the expression"),
        ("s == t", 3, "column 3: expected an operator or the end of the expression, found `=`"),
        ("a = b = c", 1, "column 1: unknown name `a`"),
        ("", 1, "column 1: expected an operand (a number, a name, `(` or `[`), found the end of the expression"),
        ("  é", 3, "column 3: expected an operand (a number, a name, `(` or `[`), found `é`"),
        ("é + ", 1, "column 1: expected an operand (a number, a name, `(` or `[`), found `é`"),
        ("s'", 3, "column 3: expected `(` after `s'`, found the end of the expression"),
    ];
    for (text, column, message) in cases {
        let e = error(text);
        assert_eq!(e.to_string(), *message, "{text}");
        assert_eq!(e.column(), Some(*column), "{text}");
    }
}

#[test]
fn type_and_name_errors_point_at_the_operand() {
    let cases: &[(&str, &str)] = &[
        ("p + s", "column 5: `+` needs a vector, found a scalar"),
        ("s - p", "column 5: `-` needs a scalar, found a vector"),
        ("p * q", "column 5: `*` of a vector (use dot(a, b) or cross(a, b)) needs a scalar, found a vector"),
        ("s / p", "column 5: `/` needs a scalar, found a vector"),
        ("p ^ 2", "column 1: `^` needs a scalar, found a vector"),
        ("norm(s)", "column 6: `norm` needs a vector, found a scalar"),
        ("dot(p, s)", "column 8: `dot` needs a vector, found a scalar"),
        ("sin(1, 2)", "column 1: `sin` takes 1 argument, found 2"),
        ("cross(p)", "column 1: `cross` takes 2 arguments, found 1"),
        ("s.x", "column 1: `.x` needs a vector, found a scalar"),
        ("p.z", "column 3: a vector has the members `x` and `y`, not `z`"),
        ("[p, s]", "column 2: a vector's component needs a scalar, found a vector"),
        ("p = s", "column 5: `=` needs a vector, found a scalar"),
        ("s + chord", "column 5: unknown name `chord`"),
        ("C'(0.5)", "column 1: unknown name `C'`"),
        ("foo(s)", "column 1: unknown name `foo`"),
        ("1 / (k - 3)", "column 5: division by a constant zero"),
        ("s / 0", "column 5: division by a constant zero"),
        ("0 ^ -1", "column 1: division by a constant zero"),
        ("ln(0)", "column 1: the constant value is not finite (-inf)"),
        ("sqrt(-k)", "column 1: the constant value is not finite (NaN)"),
        ("1e999", "column 1: the constant value is not finite (inf)"),
        ("asin(2) * s", "column 1: the constant value is not finite (NaN)"),
    ];
    for (text, message) in cases {
        assert_eq!(error(text).to_string(), *message, "{text}");
    }
}

#[test]
fn a_nan_constant_of_the_scope_is_refused_where_it_is_read() {
    let mut names = names().with_constant("bad", f64::NAN);
    let e = compile(&["s + bad"], &mut names).map(|_| ());
    assert_eq!(
        e.map_err(|e| e.to_string()),
        Err("column 5: the constant value is not finite (NaN)".to_owned())
    );
}

#[test]
fn errors_in_later_rows_name_the_row() {
    let e = compile(&["s", "p +"], &mut names())
        .map(|_| ())
        .map_err(|e| e.to_string());
    assert_eq!(
        e,
        Err("row 2: column 4: expected an operand (a number, a name, `(` or `[`), found the end of the expression".to_owned())
    );
}
