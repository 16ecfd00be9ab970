//! The single-curve file: one planar curve as a JSON object tagged by `"type"`.
//!
//! ```json
//! {"type": "bezier",  "control_points": [[0, 0], [1, 2], [3, 2], [4, 0]]}
//! {"type": "bspline", "degree": 2, "knots": [0, 0, 0, 1, 1, 1], "control_points": [...]}
//! {"type": "nurbs",   "degree": 2, "knots": [...], "control_points": [...], "weights": [...]}
//! {"type": "hermite", "p0": [0, 0], "p1": [1, 0], "t0": [1, 1], "t1": [1, -1]}
//! ```
//!
//! Apart from the tag, the fields are exactly those of the curve types' own serde form, and
//! loading goes through their validating deserializers, so a file that loads is a valid curve.
//! Errors name the file and, where serde knows it, the JSON path of the bad field.

use std::fmt;
use std::path::Path;
use std::sync::atomic::{AtomicU64, Ordering};

use anyhow::{anyhow, bail, Context, Result};
use camber_geom::{BSplineCurve2, BezierCurve2, HermiteCurve2, NurbsCurve2, ParametricCurve};
use nalgebra::Point2;
use serde::de::DeserializeOwned;
use serde::Serialize;
use serde_json::Value;

/// One planar curve of any supported kind, with f64 coordinates.
#[derive(Debug, Clone, Serialize)]
#[serde(tag = "type", rename_all = "lowercase")]
pub enum Curve {
    /// A Bézier curve over [0, 1].
    Bezier(BezierCurve2<f64>),
    /// A polynomial B-spline over its knot domain.
    #[serde(rename = "bspline")]
    BSpline(BSplineCurve2<f64>),
    /// A rational B-spline over its knot domain.
    Nurbs(NurbsCurve2<f64>),
    /// A cubic Hermite curve over [0, 1].
    Hermite(HermiteCurve2<f64>),
}

/// The tags accepted in `"type"`, in the order of [`Curve`]'s variants.
pub const CURVE_TYPES: [&str; 4] = ["bezier", "bspline", "nurbs", "hermite"];

impl Curve {
    /// The `"type"` tag of this curve.
    pub fn type_name(&self) -> &'static str {
        match self {
            Curve::Bezier(_) => "bezier",
            Curve::BSpline(_) => "bspline",
            Curve::Nurbs(_) => "nurbs",
            Curve::Hermite(_) => "hermite",
        }
    }

    /// The curve through the common [`ParametricCurve`] face.
    pub fn as_parametric(&self) -> &dyn ParametricCurve<f64, 2> {
        match self {
            Curve::Bezier(c) => c,
            Curve::BSpline(c) => c,
            Curve::Nurbs(c) => c,
            Curve::Hermite(c) => c,
        }
    }

    /// The control polygon: the control points of Bézier, B-spline and NURBS curves, and for a
    /// Hermite curve its Bézier points p0, p0 + t0/3, p1 − t1/3, p1.
    pub fn control_polygon(&self) -> Vec<Point2<f64>> {
        match self {
            Curve::Bezier(c) => c.control_points().to_vec(),
            Curve::BSpline(c) => c.control_points().to_vec(),
            Curve::Nurbs(c) => c.control_points().to_vec(),
            Curve::Hermite(c) => {
                let third = 1.0 / 3.0;
                vec![
                    c.p0(),
                    c.p0() + c.t0() * third,
                    c.p1() - c.t1() * third,
                    c.p1(),
                ]
            }
        }
    }

    /// Parses the JSON text of a curve file (a leading byte order mark is allowed). The error
    /// says what is wrong and, when known, where (`at knots[3]`); it does not name the file
    /// (see [`load`]). Unknown fields are refused.
    ///
    /// ```
    /// use camber_cli::curve_file::Curve;
    /// let c = Curve::from_json(r#"{"type": "bezier", "control_points": [[0, 0], [2, 2]]}"#)?;
    /// let p = c.as_parametric().point(0.5)?;
    /// assert!((p.x - 1.0).abs() < 1e-15);
    /// let err = Curve::from_json(r#"{"type": "bezier", "control_points": [[0, 0], [1, "y"]]}"#);
    /// assert!(format!("{:#}", err.unwrap_err()).starts_with("at control_points[1][1]"));
    /// # Ok::<(), anyhow::Error>(())
    /// ```
    pub fn from_json(text: &str) -> Result<Self> {
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        let mut value: Value = serde_json::from_str(text).map_err(json_syntax_error)?;
        let kind = kind_of(&value);
        let object = value
            .as_object_mut()
            .ok_or_else(|| anyhow!("a curve file holds one JSON object, found {kind}"))?;
        let tag = match object.remove("type") {
            Some(Value::String(s)) => s,
            Some(other) => bail!("field \"type\" must be a string, found {}", kind_of(&other)),
            None => bail!("missing field \"type\" (one of {})", CURVE_TYPES.join(", ")),
        };
        match tag.as_str() {
            "bezier" => typed(value).map(Curve::Bezier),
            "bspline" => typed(value).map(Curve::BSpline),
            "nurbs" => typed(value).map(Curve::Nurbs),
            "hermite" => typed(value).map(Curve::Hermite),
            other => bail!(
                "unknown curve type \"{other}\" (expected one of {})",
                CURVE_TYPES.join(", ")
            ),
        }
    }

    /// The curve file text: the tagged object, pretty-printed, with a final newline.
    ///
    /// # Errors
    /// A number that is not finite (an operation's result that overflowed f64): JSON would
    /// write it as `null`, so the curve is refused instead.
    pub fn to_json(&self) -> Result<String> {
        let value = serde_json::to_value(self).context("cannot encode the curve")?;
        if let Some(path) = first_null(&value, String::new()) {
            bail!("the result has a number outside the f64 range at {path}");
        }
        let mut s = serde_json::to_string_pretty(self).context("cannot encode the curve")?;
        s.push('\n');
        Ok(s)
    }
}

/// A one-line summary: type, degree, control point count and domain.
pub fn describe(curve: &Curve) -> String {
    let (a, b) = curve.as_parametric().domain();
    let degree = match curve {
        Curve::Bezier(c) => c.degree(),
        Curve::BSpline(c) => c.degree(),
        Curve::Nurbs(c) => c.degree(),
        Curve::Hermite(_) => 3,
    };
    format!(
        "{}, degree {degree}, {} control points, domain [{a}, {b}]",
        curve.type_name(),
        curve.control_polygon().len()
    )
}

/// Deserializes one curve type from the tag-less object, keeping the path of the failure.
fn typed<C: DeserializeOwned>(value: Value) -> Result<C> {
    serde_path_to_error::deserialize(value).map_err(|e| {
        let path = e.path().to_string();
        let inner = e.into_inner();
        if path == "." {
            anyhow!("{inner}")
        } else {
            anyhow!("at {path}: {inner}")
        }
    })
}

/// A JSON syntax error in plain words; an overflowing number (such as `1e999`, which would be
/// infinite) is called non-finite.
pub fn json_syntax_error(e: serde_json::Error) -> anyhow::Error {
    if e.to_string().starts_with("number out of range") {
        anyhow!(
            "non-finite number (outside the f64 range) at line {} column {}",
            e.line(),
            e.column()
        )
    } else {
        anyhow!("malformed JSON: {e}")
    }
}

/// The path (`weights[2]`) of the first `null` in `v`: where serde_json wrote a non-finite
/// number.
fn first_null(v: &Value, path: String) -> Option<String> {
    match v {
        Value::Null => Some(path),
        Value::Array(items) => items
            .iter()
            .enumerate()
            .find_map(|(i, x)| first_null(x, format!("{path}[{i}]"))),
        Value::Object(map) => map.iter().find_map(|(k, x)| {
            let sub = if path.is_empty() {
                k.clone()
            } else {
                format!("{path}.{k}")
            };
            first_null(x, sub)
        }),
        _ => None,
    }
}

/// A short name of a JSON value's kind, for messages.
fn kind_of(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

/// Reads and validates a curve file; errors start with the file name.
pub fn load(path: &Path) -> Result<Curve> {
    let text = read_text(path)?;
    Curve::from_json(&text).with_context(|| path.display().to_string())
}

/// "64 MiB" for whole mebibytes, "1000 bytes" otherwise.
fn describe_size(bytes: u64) -> String {
    if bytes >= 1 << 20 && bytes.is_multiple_of(1 << 20) {
        format!("{} MiB", bytes >> 20)
    } else {
        format!("{bytes} bytes")
    }
}

/// Writes a curve file whole (a temporary file renamed into place, see [`crate::output`]);
/// errors name the file.
pub fn save(path: &Path, curve: &Curve) -> Result<()> {
    let text = curve
        .to_json()
        .with_context(|| path.display().to_string())?;
    crate::output::write_all(&[], &[(path.to_path_buf(), text)])
}

/// The largest input file the commands read by default: 64 MiB, far above any hand-made sketch
/// or curve (the bundled 1,000-segment chain is under 1 MiB), so that a device such as
/// `/dev/zero` or a runaway file ends in an error instead of exhausting memory. Larger files
/// (a 100,000-cell ladder is 95 MB of JSON) are read once the limit is raised:
/// `camber --max-input-mib N …`, or [`set_input_limit`] / [`read_text_limited`] in a program.
pub const MAX_INPUT_BYTES: u64 = 64 << 20;

/// The most MiB `--max-input-mib` accepts (1 TiB): beyond any memory this machine class has,
/// and far from overflowing a byte count.
pub const MAX_INPUT_MIB_LIMIT: u64 = 1 << 20;

/// The limit [`read_text`] applies, in bytes ([`MAX_INPUT_BYTES`] until [`set_input_limit`]).
static INPUT_LIMIT: AtomicU64 = AtomicU64::new(MAX_INPUT_BYTES);

/// Sets the largest input file [`read_text`] reads, in bytes, for the rest of the process (the
/// command line's `--max-input-mib`). At least 1 byte.
///
/// ```
/// use camber_cli::curve_file::{input_limit, set_input_limit, MAX_INPUT_BYTES};
/// set_input_limit(200 << 20);
/// assert_eq!(input_limit(), 200 << 20);
/// set_input_limit(MAX_INPUT_BYTES);
/// ```
pub fn set_input_limit(bytes: u64) {
    INPUT_LIMIT.store(bytes.max(1), Ordering::Relaxed);
}

/// The largest input file [`read_text`] reads now, in bytes.
pub fn input_limit() -> u64 {
    INPUT_LIMIT.load(Ordering::Relaxed)
}

/// Reads a whole text file of at most [`input_limit`] bytes; a leading UTF-8 byte order mark is
/// dropped. The error names the file and the system's reason.
pub fn read_text(path: &Path) -> Result<String> {
    read_text_limited(path, input_limit())
}

/// [`read_text`] with the limit given: a file of more than `max_bytes` bytes is refused with
/// an error naming the limit and how to raise it, before more than `max_bytes` + 1 bytes are
/// read.
///
/// ```
/// let dir = tempfile::tempdir()?;
/// let path = dir.path().join("c.json");
/// std::fs::write(&path, "0123456789")?;
/// assert_eq!(camber_cli::curve_file::read_text_limited(&path, 10)?, "0123456789");
/// let err = camber_cli::curve_file::read_text_limited(&path, 9).unwrap_err().to_string();
/// assert!(err.contains("larger than 9 bytes"), "{err}");
/// # Ok::<(), anyhow::Error>(())
/// ```
pub fn read_text_limited(path: &Path, max_bytes: u64) -> Result<String> {
    let bytes = read_bytes_limited(path, max_bytes)?;
    let text = String::from_utf8(bytes).map_err(|e| {
        anyhow!(
            "{}: not UTF-8 text (at byte {})",
            path.display(),
            e.utf8_error().valid_up_to()
        )
    })?;
    Ok(match text.strip_prefix('\u{feff}') {
        Some(rest) => rest.to_owned(),
        None => text,
    })
}

/// Reads a whole file of at most [`input_limit`] bytes as bytes (a binary DXF file, say).
pub fn read_bytes(path: &Path) -> Result<Vec<u8>> {
    read_bytes_limited(path, input_limit())
}

/// [`read_bytes`] with the limit given, refused as [`read_text_limited`] refuses.
pub fn read_bytes_limited(path: &Path, max_bytes: u64) -> Result<Vec<u8>> {
    use std::io::Read as _;
    let cannot = |e: std::io::Error| anyhow!("{}: cannot read: {}", path.display(), IoReason(&e));
    let file = std::fs::File::open(path).map_err(cannot)?;
    let mut bytes = Vec::new();
    file.take(max_bytes.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(cannot)?;
    if bytes.len() as u64 > max_bytes {
        bail!(
            "{}: larger than {}, too large for an input file (raise the limit with --max-input-mib)",
            path.display(),
            describe_size(max_bytes)
        );
    }
    Ok(bytes)
}

/// Writes a whole text file; the error names the file and the system's reason.
pub fn write_text(path: &Path, text: &str) -> Result<()> {
    std::fs::write(path, text)
        .map_err(|e| anyhow!("{}: cannot write: {}", path.display(), IoReason(&e)))
}

/// An I/O error's plain reason: lower case, without the "(os error N)" suffix.
pub fn io_reason(e: &std::io::Error) -> String {
    IoReason(e).to_string()
}

/// An I/O error's plain reason without the "(os error N)" suffix.
struct IoReason<'a>(&'a std::io::Error);

impl fmt::Display for IoReason<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let text = self.0.to_string();
        let plain = text.split(" (os error").next().unwrap_or(&text);
        let mut chars = plain.chars();
        match chars.next() {
            Some(c) => write!(f, "{}{}", c.to_lowercase(), chars.as_str()),
            None => Ok(()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn message(text: &str) -> String {
        match Curve::from_json(text) {
            Ok(c) => panic!("expected an error, loaded {c:?}"),
            Err(e) => format!("{e:#}"),
        }
    }

    #[test]
    fn round_trip_keeps_the_tag_and_fields() {
        let text = r#"{"type": "nurbs", "degree": 1, "knots": [0, 0, 1, 1],
            "control_points": [[0, 0], [2, 1]], "weights": [1, 2]}"#;
        let c = Curve::from_json(text).unwrap();
        assert_eq!(c.type_name(), "nurbs");
        let again = Curve::from_json(&c.to_json().unwrap()).unwrap();
        assert_eq!(again.to_json().unwrap(), c.to_json().unwrap());
    }

    #[test]
    fn errors_say_what_and_where() {
        assert!(message("{").contains("malformed JSON"));
        assert!(message("[1]").contains("one JSON object"));
        assert!(message(r#"{"control_points": []}"#).contains("missing field \"type\""));
        assert!(message(r#"{"type": "spiral"}"#).contains("unknown curve type \"spiral\""));
        let m = message(r#"{"type": "bezier", "control_points": [[0, 0], [1, "x"]]}"#);
        assert!(m.contains("control_points[1][1]"), "{m}");
        let m = message(
            r#"{"type": "bspline", "degree": 2, "knots": [0, 0, 1, 1], "control_points": [[0, 0], [1, 1], [2, 0]]}"#,
        );
        assert!(m.contains("knot"), "{m}");
    }

    #[test]
    fn hermite_polygon_is_its_bezier_form() {
        let c = Curve::from_json(
            r#"{"type": "hermite", "p0": [0, 0], "p1": [3, 0], "t0": [3, 3], "t1": [3, -3]}"#,
        )
        .unwrap();
        let poly = c.control_polygon();
        assert_eq!(poly.len(), 4);
        assert!((poly[1] - Point2::new(1.0, 1.0)).norm() < 1e-15);
        assert!((poly[2] - Point2::new(2.0, 1.0)).norm() < 1e-15);
    }
}
