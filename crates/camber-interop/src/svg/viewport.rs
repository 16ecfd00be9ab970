//! Viewports: the map from a `viewBox` (min-x, min-y, w, h) into a viewport of size
//! (W, H) under `preserveAspectRatio`, as SVG 2 (8.2, "the viewBox to viewport transform")
//! computes it:
//!
//! sx = W/w, sy = H/h; unless the alignment is `none`, both become min(sx, sy) (`meet`, the
//! default) or max(sx, sy) (`slice`); then tx = −min-x·sx, ty = −min-y·sy, moved by
//! (W − w·sx)/2 for `xMid`, by W − w·sx for `xMax` (likewise in y). The map is
//! (x, y) ↦ (sx·x + tx, sy·y + ty).

use nalgebra::{Matrix2, Vector2};
use svgtypes::{Align, AspectRatio, ViewBox};

use super::affine::Affine;

/// The map of `view_box` into a viewport of `width` × `height` at the origin.
pub(crate) fn view_box_map(
    view_box: &ViewBox,
    width: f64,
    height: f64,
    aspect: &AspectRatio,
) -> Affine {
    let (mut sx, mut sy) = (width / view_box.w, height / view_box.h);
    if aspect.align != Align::None {
        let s = if aspect.slice { sx.max(sy) } else { sx.min(sy) };
        (sx, sy) = (s, s);
    }
    let (mut tx, mut ty) = (-view_box.x * sx, -view_box.y * sy);
    let (spare_x, spare_y) = (width - view_box.w * sx, height - view_box.h * sy);
    let (fx, fy) = match aspect.align {
        Align::None | Align::XMinYMin => (0.0, 0.0),
        Align::XMidYMin => (0.5, 0.0),
        Align::XMaxYMin => (1.0, 0.0),
        Align::XMinYMid => (0.0, 0.5),
        Align::XMidYMid => (0.5, 0.5),
        Align::XMaxYMid => (1.0, 0.5),
        Align::XMinYMax => (0.0, 1.0),
        Align::XMidYMax => (0.5, 1.0),
        Align::XMaxYMax => (1.0, 1.0),
    };
    tx += fx * spare_x;
    ty += fy * spare_y;
    Affine {
        linear: Matrix2::new(sx, 0.0, 0.0, sy),
        translation: Vector2::new(tx, ty),
    }
}

/// The translation by (x, y).
pub(crate) fn translation(x: f64, y: f64) -> Affine {
    Affine {
        linear: Matrix2::identity(),
        translation: Vector2::new(x, y),
    }
}

/// The uniform scale by `s`.
pub(crate) fn scale(s: f64) -> Affine {
    Affine {
        linear: Matrix2::new(s, 0.0, 0.0, s),
        translation: Vector2::zeros(),
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

    use super::*;
    use approx::assert_relative_eq;
    use nalgebra::Point2;
    use std::str::FromStr;

    fn map(vb: &str, w: f64, h: f64, par: &str) -> Affine {
        view_box_map(
            &ViewBox::from_str(vb).unwrap(),
            w,
            h,
            &AspectRatio::from_str(par).unwrap(),
        )
    }

    fn at(m: &Affine, x: f64, y: f64) -> Point2<f64> {
        m.apply(Point2::new(x, y))
    }

    #[test]
    fn a_view_box_of_the_viewport_shape_scales_both_ways_alike() {
        // 200 × 100 user units into 100 × 50: half size, whatever the alignment.
        for par in ["xMidYMid", "none", "xMinYMax slice"] {
            let m = map("0 0 200 100", 100.0, 50.0, par);
            assert_relative_eq!(at(&m, 200.0, 100.0), Point2::new(100.0, 50.0));
            assert_relative_eq!(at(&m, 0.0, 0.0), Point2::new(0.0, 0.0));
        }
        // A shifted origin: min-x, min-y land at the viewport's corner.
        let m = map("-10 5 20 10", 40.0, 20.0, "xMidYMid");
        assert_relative_eq!(at(&m, -10.0, 5.0), Point2::new(0.0, 0.0));
        assert_relative_eq!(at(&m, 10.0, 15.0), Point2::new(40.0, 20.0));
    }

    #[test]
    fn meet_fits_and_centres_slice_fills_and_none_stretches() {
        // A 100 × 50 box into a 200 × 200 viewport.
        // meet: s = min(2, 4) = 2; the box is 200 × 100, centred: 50 spare above.
        let m = map("0 0 100 50", 200.0, 200.0, "xMidYMid meet");
        assert_relative_eq!(at(&m, 0.0, 0.0), Point2::new(0.0, 50.0));
        assert_relative_eq!(at(&m, 100.0, 50.0), Point2::new(200.0, 150.0));
        // xMaxYMax meet: all 100 spare above.
        let m = map("0 0 100 50", 200.0, 200.0, "xMaxYMax");
        assert_relative_eq!(at(&m, 0.0, 0.0), Point2::new(0.0, 100.0));
        // slice: s = max(2, 4) = 4; the box is 400 × 200, centred: 100 cut on each side.
        let m = map("0 0 100 50", 200.0, 200.0, "xMidYMid slice");
        assert_relative_eq!(at(&m, 0.0, 0.0), Point2::new(-100.0, 0.0));
        assert_relative_eq!(at(&m, 100.0, 50.0), Point2::new(300.0, 200.0));
        // none: sx = 2, sy = 4.
        let m = map("0 0 100 50", 200.0, 200.0, "none");
        assert_relative_eq!(at(&m, 100.0, 50.0), Point2::new(200.0, 200.0));
        assert_relative_eq!(at(&m, 50.0, 0.0), Point2::new(100.0, 0.0));
    }
}
