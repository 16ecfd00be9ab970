//! The basic shapes and paths of a document, each drawn under its element's transform:
//! `path` as its path data; `line`, `polyline`, `polygon` and `rect` (rounded corners as
//! quarter arcs) as the path SVG 2 says they equal; `circle` and `ellipse` as a circle or an
//! ellipse entity. Their lengths may carry units ([`super::units`]); a length that cannot be
//! made user units (`em`, `ex`, a percentage with no viewport) lists its shape as skipped.

use nalgebra::Point2;
use roxmltree::Node;
use svgtypes::PathSegment;

use super::affine::Affine;
use super::builder::Builder;
use super::errors::{Error, Item};
use super::units::{user_units, Axis, Unresolved};

/// Where a shape is drawn: its element, its map to the sketch's frame (before the y flip) and
/// the size of its viewport in user units (for percentages), when known.
pub(crate) struct Place<'p> {
    pub(crate) item: &'p Item,
    pub(crate) ctm: &'p Affine,
    pub(crate) viewport: Option<(f64, f64)>,
}

pub(crate) fn malformed(item: &Item, attribute: &'static str, value: &str, message: &str) -> Error {
    Error::MalformedAttribute {
        item: item.clone(),
        attribute,
        value: value.chars().take(80).collect(),
        message: message.to_string(),
    }
}

/// A length attribute in user units (absent: `default`); `Ok(Err(reason))` for a length that
/// is well written but cannot be converted.
pub(crate) fn length(
    node: &Node<'_, '_>,
    item: &Item,
    attribute: &'static str,
    default: f64,
    viewport: Option<(f64, f64)>,
) -> Result<Result<f64, String>, Error> {
    let Some(text) = node.attribute(attribute) else {
        return Ok(Ok(default));
    };
    match user_units(text, Axis::of(attribute), viewport) {
        Ok(v) => Ok(Ok(v)),
        Err(Unresolved::Malformed(m)) => Err(malformed(item, attribute, text, &m)),
        Err(Unresolved::Unconvertible(why)) => Ok(Err(format!(
            "attribute {attribute}=\"{}\" cannot be made user units: {why}",
            text.chars().take(80).collect::<String>()
        ))),
    }
}

/// Reads the named lengths; `None` (the shape listed as skipped) when one cannot be converted.
fn lengths<const N: usize>(
    b: &mut Builder<'_>,
    node: &Node<'_, '_>,
    place: &Place<'_>,
    names: [&'static str; N],
) -> Result<Option<[f64; N]>, Error> {
    let mut out = [0.0; N];
    for (slot, name) in out.iter_mut().zip(names) {
        match length(node, place.item, name, 0.0, place.viewport)? {
            Ok(v) => *slot = v,
            Err(reason) => {
                b.skip(place.item.to_string(), reason);
                return Ok(None);
            }
        }
    }
    Ok(Some(out))
}

/// Imports one element that is not a container.
pub(crate) fn shape(
    b: &mut Builder<'_>,
    node: &Node<'_, '_>,
    place: &Place<'_>,
) -> Result<(), Error> {
    let (item, ctm) = (place.item, place.ctm);
    let abs = true;
    match node.tag_name().name() {
        "path" => match node.attribute("d") {
            Some(d) => b.add_path(item, svgtypes::PathParser::from(d), ctm),
            None => {
                b.skip(
                    item.to_string(),
                    "it has no d attribute, so it draws nothing".into(),
                );
                Ok(())
            }
        },
        "line" => {
            let Some([x1, y1, x2, y2]) = lengths(b, node, place, ["x1", "y1", "x2", "y2"])? else {
                return Ok(());
            };
            let segs = [
                PathSegment::MoveTo { abs, x: x1, y: y1 },
                PathSegment::LineTo { abs, x: x2, y: y2 },
            ];
            b.add_path(item, segs.into_iter().map(Ok), ctm)
        }
        tag @ ("polyline" | "polygon") => {
            let text = node.attribute("points").unwrap_or("");
            let mut segs: Vec<PathSegment> = Vec::new();
            for (k, (x, y)) in svgtypes::PointsParser::from(text).enumerate() {
                segs.push(if k == 0 {
                    PathSegment::MoveTo { abs, x, y }
                } else {
                    PathSegment::LineTo { abs, x, y }
                });
            }
            if segs.len() < 2 {
                b.skip(
                    item.to_string(),
                    "fewer than two points draw nothing".into(),
                );
                return Ok(());
            }
            if tag == "polygon" {
                segs.push(PathSegment::ClosePath { abs });
            }
            b.add_path(item, segs.into_iter().map(Ok), ctm)
        }
        "rect" => rect(b, node, place),
        "circle" => {
            let Some([cx, cy, r]) = lengths(b, node, place, ["cx", "cy", "r"])? else {
                return Ok(());
            };
            if r <= 0.0 {
                b.skip(
                    item.to_string(),
                    format!("its radius {r} is not positive, so it draws nothing"),
                );
                return Ok(());
            }
            b.add_ellipse(item, Point2::new(cx, cy), r, r, ctm)
        }
        "ellipse" => {
            let Some([cx, cy, rx, ry]) = lengths(b, node, place, ["cx", "cy", "rx", "ry"])? else {
                return Ok(());
            };
            if rx <= 0.0 || ry <= 0.0 {
                b.skip(
                    item.to_string(),
                    format!("its radii {rx}, {ry} are not both positive, so it draws nothing"),
                );
                return Ok(());
            }
            b.add_ellipse(item, Point2::new(cx, cy), rx, ry, ctm)
        }
        "text" | "image" | "foreignObject" => {
            b.skip(
                item.to_string(),
                "not geometry the importer reads (text and images)".into(),
            );
            Ok(())
        }
        other => {
            b.skip(
                item.to_string(),
                format!("<{other}> is not an element the importer reads"),
            );
            Ok(())
        }
    }
}

/// A rectangle as SVG 2 defines its path: sides, and quarter arcs of radii (rx, ry) at the
/// corners (one given radius serves for both; each at most half the side).
fn rect(b: &mut Builder<'_>, node: &Node<'_, '_>, place: &Place<'_>) -> Result<(), Error> {
    let (item, ctm) = (place.item, place.ctm);
    let Some([x, y, w, h]) = lengths(b, node, place, ["x", "y", "width", "height"])? else {
        return Ok(());
    };
    if w <= 0.0 || h <= 0.0 {
        b.skip(
            item.to_string(),
            format!("its size {w} × {h} is not positive, so it draws nothing"),
        );
        return Ok(());
    }
    // A radius absent or `auto` takes the other's value; one that cannot be converted is
    // listed and taken as absent.
    let mut given = |name: &'static str| -> Result<Option<f64>, Error> {
        match node.attribute(name) {
            None | Some("auto") => Ok(None),
            Some(_) => match length(node, item, name, 0.0, place.viewport)? {
                Ok(v) => Ok(Some(v)),
                Err(reason) => {
                    b.skip(
                        item.to_string(),
                        format!("{reason}; the corners are drawn as if it were not given"),
                    );
                    Ok(None)
                }
            },
        }
    };
    let (rx, ry) = match (given("rx")?, given("ry")?) {
        (Some(rx), Some(ry)) => (rx, ry),
        (Some(r), None) | (None, Some(r)) => (r, r),
        (None, None) => (0.0, 0.0),
    };
    let (rx, ry) = (rx.max(0.0).min(w / 2.0), ry.max(0.0).min(h / 2.0));
    let abs = true;
    let mut segs = Vec::with_capacity(10);
    let corner = |x, y| PathSegment::EllipticalArc {
        abs,
        rx,
        ry,
        x_axis_rotation: 0.0,
        large_arc: false,
        sweep: true,
        x,
        y,
    };
    let round = rx > 0.0 && ry > 0.0;
    segs.push(PathSegment::MoveTo { abs, x: x + rx, y });
    if w > 2.0 * rx {
        segs.push(PathSegment::HorizontalLineTo { abs, x: x + w - rx });
    }
    if round {
        segs.push(corner(x + w, y + ry));
    }
    if h > 2.0 * ry {
        segs.push(PathSegment::VerticalLineTo { abs, y: y + h - ry });
    }
    if round {
        segs.push(corner(x + w - rx, y + h));
    }
    if w > 2.0 * rx {
        segs.push(PathSegment::HorizontalLineTo { abs, x: x + rx });
    }
    if round {
        segs.push(corner(x, y + h - ry));
    }
    if h > 2.0 * ry {
        segs.push(PathSegment::VerticalLineTo { abs, y: y + ry });
    }
    if round {
        segs.push(corner(x + rx, y));
    }
    segs.push(PathSegment::ClosePath { abs });
    b.add_path(item, segs.into_iter().map(Ok), ctm)
}
