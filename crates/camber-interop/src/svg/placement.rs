//! Where an `<svg>` (or a `<symbol>` drawn by a `use`) puts its content: the map from its user
//! units to its parent's, and the size of its viewport in its own user units (what its
//! percentages are of).
//!
//! - The root: with [`SketchUnits::User`] the map is the identity (the sketch is in the
//!   root's user units); with [`SketchUnits::Physical`] it is the viewBox-to-viewport map into
//!   `width` × `height` (in px, at 96 px per inch), then px to the unit. A root missing one of
//!   `width`, `height` takes it from the viewBox's aspect ratio, missing both (or written as
//!   percentages, of a page the file does not have) the viewBox's size as px.
//! - A nested `svg`: translated by (`x`, `y`), its viewBox mapped into `width` × `height`
//!   (default 100% of the parent's viewport); a `use` may give the width and height. Its
//!   viewport does not clip (the importer draws no clipping).

use std::str::FromStr;

use roxmltree::Node;
use svgtypes::{Align, AspectRatio, Length, ViewBox};

use super::affine::Affine;
use super::builder::Builder;
use super::errors::{Error, Item};
use super::options::SketchUnits;
use super::shapes::{length, malformed};
use super::units::absolute;
use super::viewport::{scale, translation, view_box_map};

/// The map of an element's content into its parent's user units and its viewport's size.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Placed {
    pub(crate) map: Affine,
    pub(crate) viewport: Option<(f64, f64)>,
}

fn view_box(node: &Node<'_, '_>, item: &Item) -> Result<Option<ViewBox>, Error> {
    let Some(text) = node.attribute("viewBox") else {
        return Ok(None);
    };
    let vb =
        ViewBox::from_str(text).map_err(|e| malformed(item, "viewBox", text, &e.to_string()))?;
    if [vb.x, vb.y, vb.w, vb.h].iter().all(|v| v.is_finite()) {
        Ok(Some(vb))
    } else {
        Err(malformed(item, "viewBox", text, "a number is not finite"))
    }
}

fn aspect(node: &Node<'_, '_>, item: &Item) -> Result<AspectRatio, Error> {
    match node.attribute("preserveAspectRatio") {
        None => Ok(AspectRatio {
            defer: false,
            align: Align::XMidYMid,
            slice: false,
        }),
        Some(text) => AspectRatio::from_str(text)
            .map_err(|e| malformed(item, "preserveAspectRatio", text, &e.to_string())),
    }
}

/// The root's `width` or `height` in px: `Ok(None)` when absent or relative (a percentage,
/// `em`); an error when unreadable or not positive.
fn root_size(
    node: &Node<'_, '_>,
    item: &Item,
    attribute: &'static str,
) -> Result<Option<f64>, Error> {
    let Some(text) = node.attribute(attribute) else {
        return Ok(None);
    };
    let l = Length::from_str(text).map_err(|e| malformed(item, attribute, text, &e.to_string()))?;
    let Some(px) = absolute(&l) else {
        return Ok(None);
    };
    if !px.is_finite() || px <= 0.0 {
        return Err(malformed(
            item,
            attribute,
            text,
            "a viewport's size must be a positive finite length",
        ));
    }
    Ok(Some(px))
}

/// The root `<svg>`'s placement under `units`.
pub(crate) fn root(
    b: &mut Builder<'_>,
    node: &Node<'_, '_>,
    item: &Item,
    units: SketchUnits,
) -> Result<Placed, Error> {
    let vb = view_box(node, item)?;
    let par = aspect(node, item)?;
    let (w, h) = (
        root_size(node, item, "width")?,
        root_size(node, item, "height")?,
    );
    let (to_viewport, viewport) = match vb {
        Some(vb) => {
            let (w, h) = match (w, h) {
                (Some(w), Some(h)) => (w, h),
                (Some(w), None) => (w, w * vb.h / vb.w),
                (None, Some(h)) => (h * vb.w / vb.h, h),
                (None, None) => (vb.w, vb.h),
            };
            (view_box_map(&vb, w, h, &par), Some((vb.w, vb.h)))
        }
        None => (Affine::identity(), w.zip(h)),
    };
    let map = match units {
        SketchUnits::User => Affine::identity(),
        SketchUnits::Physical(unit) => {
            if w.is_none() && h.is_none() {
                b.skip(
                    item.to_string(),
                    "the root has no absolute width or height, so its physical size is not known: one user unit of its viewBox is taken as 1 px".into(),
                );
            }
            scale(1.0 / unit.in_px()).then_inner(&to_viewport)
        }
    };
    if !map.is_finite() {
        return Err(malformed(
            item,
            "viewBox",
            node.attribute("viewBox").unwrap_or(""),
            "the map to the viewport overflows f64",
        ));
    }
    Ok(Placed { map, viewport })
}

/// A nested `svg`'s placement, or a `symbol`'s drawn by a `use` (`instance`: the `use`'s
/// width and height where given); `None` (listed) when it draws nothing or its size cannot be
/// known.
pub(crate) fn nested(
    b: &mut Builder<'_>,
    node: &Node<'_, '_>,
    item: &Item,
    parent: Option<(f64, f64)>,
    instance: (Option<f64>, Option<f64>),
) -> Result<Option<Placed>, Error> {
    // A length given by the use, else written, else its default: 0 for x and y, 100% of the
    // parent's viewport for width and height.
    let read =
        |attribute: &'static str, given: Option<f64>| -> Result<Result<f64, String>, Error> {
            if let Some(v) = given {
                return Ok(Ok(v));
            }
            if node.has_attribute(attribute) {
                return length(node, item, attribute, 0.0, parent);
            }
            let side = match attribute {
                "width" => parent.map(|p| p.0),
                "height" => parent.map(|p| p.1),
                _ => return Ok(Ok(0.0)),
            };
            Ok(side.ok_or_else(|| {
                format!("its {attribute} is 100% of a viewport whose size is not known")
            }))
        };
    let symbol = node.tag_name().name() == "symbol";
    let (x, y) = if symbol {
        (Ok(0.0), Ok(0.0))
    } else {
        (read("x", None)?, read("y", None)?)
    };
    let (w, h) = (read("width", instance.0)?, read("height", instance.1)?);
    let (x, y) = match (x, y) {
        (Ok(x), Ok(y)) => (x, y),
        (Err(reason), _) | (_, Err(reason)) => {
            b.skip(
                item.to_string(),
                format!("{reason}, so its content is not placed"),
            );
            return Ok(None);
        }
    };
    let vb = view_box(node, item)?;
    let size = match (w, h) {
        (Ok(w), Ok(h)) => Some((w, h)),
        (Err(reason), _) | (_, Err(reason)) => {
            if vb.is_some() {
                b.skip(
                    item.to_string(),
                    format!("{reason}, so its viewBox cannot be placed"),
                );
                return Ok(None);
            }
            None
        }
    };
    if let Some((w, h)) = size {
        if w <= 0.0 || h <= 0.0 {
            b.skip(
                item.to_string(),
                format!("its viewport {w} × {h} is not positive, so it draws nothing"),
            );
            return Ok(None);
        }
    }
    let at = translation(x, y);
    Ok(Some(match (vb, size) {
        (Some(vb), Some((w, h))) => Placed {
            map: at.then_inner(&view_box_map(&vb, w, h, &aspect(node, item)?)),
            viewport: Some((vb.w, vb.h)),
        },
        _ => Placed {
            map: at,
            viewport: size,
        },
    }))
}
