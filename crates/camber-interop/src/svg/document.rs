//! Whole SVG documents: every `<path>` (and the basic shapes) under the root `<svg>`, each
//! drawn under the `transform` of its ancestors composed from the root inwards with its own.
//!
//! - Groups (`g`, `a`, `switch`, a nested `svg` without placement) are walked; a nested `svg`
//!   with `x`, `y` or `viewBox` is listed as skipped (its viewport placement is not applied).
//! - `path` is read as path data; `line`, `polyline`, `polygon` and `rect` (rounded corners
//!   as quarter arcs) as the path SVG 2 says they equal; `circle` and `ellipse` become a
//!   circle or an ellipse entity (a circle under a non-uniform scale becomes an ellipse).
//! - Definitions (`defs`, `symbol`, `clipPath`, `mask`, `marker`, `pattern`) draw nothing
//!   themselves: one holding shapes is listed as skipped with their count.
//! - `text`, `image`, `use`, `foreignObject` and SVG elements the importer does not know are
//!   listed as skipped; elements that draw nothing (`title`, `desc`, `metadata`, `style`,
//!   gradients, filters, …) and elements of other namespaces (an editor's metadata) are not.
//! - Lengths are user units (plain numbers or `px`); another unit lists its shape as skipped.
//!   The root's `viewBox`, `width` and `height` are not applied: the sketch is in user units.

use std::str::FromStr;

use nalgebra::Point2;
use roxmltree::{Document, Node, ParsingOptions};
use svgtypes::PathSegment;

use super::affine::Affine;
use super::builder::Builder;
use super::errors::{Error, Item};
use super::nesting::{self, Finding};
use super::options::SvgOptions;
use crate::Imported;

const SVG_NAMESPACE: &str = "http://www.w3.org/2000/svg";

/// Elements that only hold definitions drawn elsewhere.
const DEFINITIONS: &[&str] = &["defs", "symbol", "clipPath", "mask", "marker", "pattern"];

/// Elements that draw nothing.
const NOT_DRAWN: &[&str] = &[
    "title",
    "desc",
    "metadata",
    "style",
    "script",
    "linearGradient",
    "radialGradient",
    "stop",
    "filter",
    "view",
    "animate",
    "animateMotion",
    "animateTransform",
    "set",
    "mpath",
    "cursor",
    "font",
    "font-face",
    "color-profile",
];

const SHAPES: &[&str] = &[
    "path", "rect", "circle", "ellipse", "line", "polyline", "polygon",
];

/// The sketch of every path and basic shape of an SVG document (see the module
/// documentation), under `options`.
///
/// ```
/// use camber_interop::svg::{import_document, SvgOptions};
/// let doc = r#"<svg xmlns="http://www.w3.org/2000/svg">
///   <g transform="translate(10 0)"><path id="edge" d="M 0 0 L 5 0"/></g>
///   <circle cx="0" cy="0" r="2"/>
///   <text x="0" y="0">label</text>
/// </svg>"#;
/// let imported = import_document(doc, &SvgOptions::default())?;
/// let kinds: Vec<&str> = imported.sketch.entities().map(|(_, e)| e.kind_name()).collect();
/// assert_eq!(kinds, ["line", "circle"]);
/// assert_eq!(imported.sketch.entities().next().map(|(_, e)| e.points()[0].x), Some(10.0));
/// assert_eq!(imported.skipped.len(), 1); // the text, with why
/// # Ok::<(), camber_interop::svg::Error>(())
/// ```
///
/// # Errors
/// [`Error::InputTooLarge`] (checked first); [`Error::Xml`] for a document that is not XML or
/// has more than [`SvgOptions::max_nodes`] nodes; [`Error::NotSvg`]; [`Error::TooDeep`];
/// [`Error::MalformedAttribute`] for a `transform` or a shape's number that cannot be read;
/// the errors of [`import_path`](super::import_path) for a path's data, naming the element.
pub fn import_document(svg_text: &str, options: &SvgOptions) -> Result<Imported, Error> {
    if svg_text.len() > options.max_input_bytes {
        return Err(Error::InputTooLarge {
            bytes: svg_text.len(),
            max: options.max_input_bytes,
        });
    }
    match nesting::scan(svg_text, options.max_depth) {
        Some(Finding::TooDeep(t)) => {
            return Err(Error::TooDeep {
                item: Item::Element {
                    tag: t.tag,
                    id: None,
                    line: line_of(svg_text, t.offset),
                },
                depth: t.depth,
                max: options.max_depth,
            })
        }
        Some(Finding::MarkupInDtd { offset }) => {
            return Err(Error::Xml {
                message: format!(
                    "the DTD at line {} could declare elements in its entities, which are not read",
                    line_of(svg_text, offset)
                ),
            })
        }
        None => {}
    }
    // Editors write DOCTYPEs with entity declarations; the reader guards against entity
    // expansion attacks itself, the node budget bounds the rest, and the scan above refused
    // entities that could hold elements.
    let parsing = ParsingOptions {
        allow_dtd: true,
        nodes_limit: options.max_nodes,
    };
    let doc = Document::parse_with_options(svg_text, parsing).map_err(|e| Error::Xml {
        message: e.to_string(),
    })?;
    let root = doc.root_element();
    if root.tag_name().name() != "svg" {
        return Err(Error::NotSvg {
            root: root.tag_name().name().to_string(),
        });
    }
    let mut b = Builder::new(options);
    // Depth-first in document order with an explicit stack: nesting cannot overflow the
    // call stack, and the depth budget is checked on the way down.
    let mut stack: Vec<(Node<'_, '_>, Affine, usize)> = vec![(root, Affine::identity(), 0)];
    while let Some((node, parent_ctm, depth)) = stack.pop() {
        let item = item_of(&doc, &node);
        if depth > options.max_depth {
            return Err(Error::TooDeep {
                item,
                depth,
                max: options.max_depth,
            });
        }
        let ctm = match node.attribute("transform") {
            Some(t) => parent_ctm.then_inner(&transform(&item, t)?),
            None => parent_ctm,
        };
        if !ctm.is_finite() {
            return Err(malformed(
                &item,
                "transform",
                node.attribute("transform").unwrap_or(""),
                "the composed transform overflows f64",
            ));
        }
        let tag = node.tag_name().name();
        let descend = match tag {
            "svg" if depth > 0 && ["x", "y", "viewBox"].iter().any(|a| node.has_attribute(*a)) => {
                b.skip(
                    item.to_string(),
                    "a nested viewport with x, y or viewBox: its placement is not applied, so its content is not imported".into(),
                );
                false
            }
            "svg" | "g" | "a" | "switch" => true,
            _ if DEFINITIONS.contains(&tag) => {
                let shapes = node
                    .descendants()
                    .filter(|n| n.is_element() && SHAPES.contains(&n.tag_name().name()))
                    .count();
                if shapes > 0 {
                    b.skip(
                        item.to_string(),
                        format!("definitions are not drawn where they stand; the {shapes} shape(s) inside are not imported"),
                    );
                }
                false
            }
            _ if NOT_DRAWN.contains(&tag) => false,
            _ => {
                if det_is_zero(&ctm) && SHAPES.contains(&tag) {
                    b.skip(
                        item.to_string(),
                        "its transform is singular, so SVG draws nothing".into(),
                    );
                } else {
                    shape(&mut b, &node, &item, &ctm)?;
                }
                false
            }
        };
        if descend {
            let children: Vec<Node<'_, '_>> = node
                .children()
                .filter(|n| n.is_element() && is_svg(n))
                .collect();
            for child in children.into_iter().rev() {
                stack.push((child, ctm, depth + 1));
            }
        }
    }
    Ok(b.finish())
}

/// The line (from 1) of a byte offset.
fn line_of(text: &str, offset: usize) -> u32 {
    let before = text.as_bytes().get(..offset).unwrap_or(text.as_bytes());
    let lines = before.iter().filter(|c| **c == b'\n').count() + 1;
    u32::try_from(lines).unwrap_or(u32::MAX)
}

fn is_svg(node: &Node<'_, '_>) -> bool {
    matches!(node.tag_name().namespace(), None | Some(SVG_NAMESPACE))
}

fn det_is_zero(ctm: &Affine) -> bool {
    ctm.determinant().abs() <= 0.0
}

fn item_of(doc: &Document<'_>, node: &Node<'_, '_>) -> Item {
    Item::Element {
        tag: node.tag_name().name().to_string(),
        id: node.attribute("id").map(str::to_string),
        line: doc.text_pos_at(node.range().start).row,
    }
}

fn malformed(item: &Item, attribute: &'static str, value: &str, message: &str) -> Error {
    Error::MalformedAttribute {
        item: item.clone(),
        attribute,
        value: value.chars().take(80).collect(),
        message: message.to_string(),
    }
}

fn transform(item: &Item, text: &str) -> Result<Affine, Error> {
    let t = svgtypes::Transform::from_str(text)
        .map_err(|e| malformed(item, "transform", text, &e.to_string()))?;
    let a = Affine::from_svg(&t);
    if a.is_finite() {
        Ok(a)
    } else {
        Err(malformed(item, "transform", text, "a number is not finite"))
    }
}

/// A length attribute in user units (absent: `default`); `Ok(None)` for a unit other than
/// none or `px`.
fn length(
    node: &Node<'_, '_>,
    item: &Item,
    attribute: &'static str,
    default: f64,
) -> Result<Option<f64>, Error> {
    let Some(text) = node.attribute(attribute) else {
        return Ok(Some(default));
    };
    let l = svgtypes::Length::from_str(text)
        .map_err(|e| malformed(item, attribute, text, &e.to_string()))?;
    if !l.number.is_finite() {
        return Err(malformed(item, attribute, text, "the number is not finite"));
    }
    Ok(match l.unit {
        svgtypes::LengthUnit::None | svgtypes::LengthUnit::Px => Some(l.number),
        _ => None,
    })
}

/// Reads the named lengths; `None` (the shape listed as skipped) when one has another unit.
fn lengths<const N: usize>(
    b: &mut Builder<'_>,
    node: &Node<'_, '_>,
    item: &Item,
    names: [&'static str; N],
) -> Result<Option<[f64; N]>, Error> {
    let mut out = [0.0; N];
    for (slot, name) in out.iter_mut().zip(names) {
        match length(node, item, name, 0.0)? {
            Some(v) => *slot = v,
            None => {
                b.skip(
                    item.to_string(),
                    format!(
                        "attribute {name} has a unit other than user units (px): not converted"
                    ),
                );
                return Ok(None);
            }
        }
    }
    Ok(Some(out))
}

/// Imports one element that is not a container.
fn shape(b: &mut Builder<'_>, node: &Node<'_, '_>, item: &Item, ctm: &Affine) -> Result<(), Error> {
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
            let Some([x1, y1, x2, y2]) = lengths(b, node, item, ["x1", "y1", "x2", "y2"])? else {
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
        "rect" => rect(b, node, item, ctm),
        "circle" => {
            let Some([cx, cy, r]) = lengths(b, node, item, ["cx", "cy", "r"])? else {
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
            let Some([cx, cy, rx, ry]) = lengths(b, node, item, ["cx", "cy", "rx", "ry"])? else {
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
        "text" | "image" | "use" | "foreignObject" => {
            b.skip(
                item.to_string(),
                "not geometry the importer reads (text, images and references are not followed)"
                    .into(),
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
fn rect(b: &mut Builder<'_>, node: &Node<'_, '_>, item: &Item, ctm: &Affine) -> Result<(), Error> {
    let Some([x, y, w, h]) = lengths(b, node, item, ["x", "y", "width", "height"])? else {
        return Ok(());
    };
    if w <= 0.0 || h <= 0.0 {
        b.skip(
            item.to_string(),
            format!("its size {w} × {h} is not positive, so it draws nothing"),
        );
        return Ok(());
    }
    let given = |name| {
        node.has_attribute(name)
            .then(|| length(node, item, name, 0.0))
            .transpose()
    };
    let (rx, ry) = match (given("rx")?.flatten(), given("ry")?.flatten()) {
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
