//! serde's messages in the words of the file format: a JSON user reads "expected a number",
//! not "expected f64", and "expected an object", not "expected struct PairForm" (a Rust type
//! name of this crate's own).

/// Rewrites the vocabulary of a serde message (`invalid type: map, expected struct X`) into
/// the file format's (`invalid type: object, expected an object`). Messages without serde's
/// words pass unchanged.
///
/// ```ignore
/// assert_eq!(plain_words("invalid type: string \"a\", expected f64"),
///            "invalid type: string \"a\", expected a number");
/// ```
pub(super) fn plain_words(message: &str) -> String {
    let (head, expected) = match message.rfind("expected ") {
        Some(at) => (&message[..at], Some(&message[at + "expected ".len()..])),
        None => (message, None),
    };
    let mut out = unexpected_words(head);
    if let Some(what) = expected {
        out.push_str("expected ");
        out.push_str(&expected_words(what));
    }
    out
}

/// serde's names of the value found (`map`, `sequence`, `floating point `1.5``) as JSON's.
fn unexpected_words(head: &str) -> String {
    head.replace("invalid type: map,", "invalid type: object,")
        .replace("invalid type: sequence,", "invalid type: array,")
        .replace("invalid type: unit value,", "invalid type: null,")
        .replace("floating point `", "number `")
}

/// What serde expected, in the file format's words.
fn expected_words(what: &str) -> String {
    // "… with 3 elements": serde saw an array where a struct or tuple was expected.
    let (kind, count) = match what.rsplit_once(" with ") {
        Some((k, n)) if n.ends_with(" elements") || n.ends_with(" element") => {
            (k, n.split(' ').next())
        }
        _ => (what, None),
    };
    let primitive = match kind {
        "f64" | "f32" => Some("a number"),
        "usize" | "u64" | "u32" | "u16" | "u8" => Some("a non-negative integer"),
        "isize" | "i64" | "i32" | "i16" | "i8" => Some("an integer"),
        "a sequence" => Some("an array"),
        "a map" => Some("an object"),
        "string or map" => Some("a name or an object"),
        "a borrowed string" => Some("a string"),
        "bool" => Some("true or false"),
        _ => None,
    };
    if let Some(p) = primitive {
        return p.to_owned();
    }
    let rust_type = [
        "struct variant ",
        "struct ",
        "unit struct ",
        "newtype struct ",
    ]
    .iter()
    .any(|p| kind.starts_with(p));
    if kind.starts_with("tuple variant ") || kind.starts_with("tuple struct ") {
        return match count {
            Some(n) => format!("an array of {n} values"),
            None => "an array".to_owned(),
        };
    }
    if rust_type {
        return "an object".to_owned();
    }
    if kind.starts_with("enum ") {
        return "a name or an object".to_owned();
    }
    what.to_owned()
}

#[cfg(test)]
mod tests {
    use super::plain_words;

    #[test]
    fn rust_type_names_become_the_file_formats_words() {
        for (serde, plain) in [
            (
                "invalid type: string \"a\", expected f64",
                "invalid type: string \"a\", expected a number",
            ),
            (
                "invalid value: integer `-1`, expected usize",
                "invalid value: integer `-1`, expected a non-negative integer",
            ),
            (
                "invalid type: floating point `1.5`, expected u64",
                "invalid type: number `1.5`, expected a non-negative integer",
            ),
            (
                "invalid type: integer `3`, expected struct PairForm",
                "invalid type: integer `3`, expected an object",
            ),
            (
                "invalid length 1, expected tuple variant Arg::FreeOf with 2 elements",
                "invalid length 1, expected an array of 2 values",
            ),
            (
                "invalid type: map, expected a sequence",
                "invalid type: object, expected an array",
            ),
            (
                "invalid type: null, expected string or map",
                "invalid type: null, expected a name or an object",
            ),
            (
                "unknown field `a`, expected one of `first`, `second`",
                "unknown field `a`, expected one of `first`, `second`",
            ),
            ("missing field `id`", "missing field `id`"),
        ] {
            assert_eq!(plain_words(serde), plain);
        }
    }
}
