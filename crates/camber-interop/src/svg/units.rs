//! Lengths with units, in user units: SVG takes a user unit as one CSS pixel, and CSS fixes
//! the absolute units at 96 px per inch, so 1 in = 96, 1 cm = 96/2.54, 1 mm = 96/25.4,
//! 1 pt = 96/72 (1/72 in), 1 pc = 16 (12 pt) user units. A percentage is of the nearest
//! viewport's size in user units: its width for x-like lengths, its height for y-like ones and
//! √((w² + h²)/2) for the rest (a circle's `r`), as SVG 2 defines. `em` and `ex` depend on the
//! font, which the importer does not read.

use std::str::FromStr;

use svgtypes::{Length, LengthUnit};

/// CSS pixels (SVG user units) per inch.
pub const PX_PER_INCH: f64 = 96.0;

/// A unit of length a sketch can be made in ([`SketchUnits::Physical`](super::SketchUnits)).
///
/// ```
/// use camber_interop::svg::Unit;
/// assert_eq!(Unit::Inch.in_px(), 96.0);
/// assert!((Unit::Millimetre.in_px() * 25.4 - 96.0).abs() < 1e-12);
/// assert_eq!(Unit::Point.in_px(), 96.0 / 72.0);
/// assert_eq!(Unit::Millimetre.symbol(), "mm");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Unit {
    /// The CSS pixel, 1/96 in.
    Pixel,
    /// The millimetre.
    Millimetre,
    /// The centimetre.
    Centimetre,
    /// The inch.
    Inch,
    /// The point, 1/72 in.
    Point,
    /// The pica, 12 pt = 1/6 in.
    Pica,
}

impl Unit {
    /// How many CSS pixels (user units) one of this unit is, at 96 px per inch.
    pub fn in_px(self) -> f64 {
        match self {
            Unit::Pixel => 1.0,
            Unit::Millimetre => PX_PER_INCH / 25.4,
            Unit::Centimetre => PX_PER_INCH / 2.54,
            Unit::Inch => PX_PER_INCH,
            Unit::Point => PX_PER_INCH / 72.0,
            Unit::Pica => PX_PER_INCH / 6.0,
        }
    }

    /// Its CSS symbol (`px`, `mm`, `cm`, `in`, `pt`, `pc`).
    pub fn symbol(self) -> &'static str {
        match self {
            Unit::Pixel => "px",
            Unit::Millimetre => "mm",
            Unit::Centimetre => "cm",
            Unit::Inch => "in",
            Unit::Point => "pt",
            Unit::Pica => "pc",
        }
    }

    /// The unit of a CSS symbol, `None` for any other text.
    ///
    /// ```
    /// use camber_interop::svg::Unit;
    /// assert_eq!(Unit::from_symbol("mm"), Some(Unit::Millimetre));
    /// assert_eq!(Unit::from_symbol("furlong"), None);
    /// ```
    pub fn from_symbol(symbol: &str) -> Option<Unit> {
        [
            Unit::Pixel,
            Unit::Millimetre,
            Unit::Centimetre,
            Unit::Inch,
            Unit::Point,
            Unit::Pica,
        ]
        .into_iter()
        .find(|u| u.symbol() == symbol)
    }
}

/// Which size of the viewport a percentage is of.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Axis {
    /// x, cx, x1, x2, width, rx.
    Width,
    /// y, cy, y1, y2, height, ry.
    Height,
    /// r: √((w² + h²)/2).
    Diagonal,
}

impl Axis {
    /// The axis of a length attribute by its name.
    pub(crate) fn of(attribute: &str) -> Axis {
        match attribute {
            "x" | "cx" | "x1" | "x2" | "width" | "rx" | "dx" => Axis::Width,
            "y" | "cy" | "y1" | "y2" | "height" | "ry" | "dy" => Axis::Height,
            _ => Axis::Diagonal,
        }
    }
}

/// A length that could not be made user units.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Unresolved {
    /// The text is not a length (svgtypes' message), or its number is not finite.
    Malformed(String),
    /// A length that is well written but cannot be converted (why, in a phrase).
    Unconvertible(&'static str),
}

/// The length `text` in user units, percentages being of `viewport` (its width and height in
/// user units, `None` where no viewport size is known).
pub(crate) fn user_units(
    text: &str,
    axis: Axis,
    viewport: Option<(f64, f64)>,
) -> Result<f64, Unresolved> {
    let l = Length::from_str(text).map_err(|e| Unresolved::Malformed(e.to_string()))?;
    if !l.number.is_finite() {
        return Err(Unresolved::Malformed("the number is not finite".into()));
    }
    let v = match absolute(&l) {
        Some(px) => px,
        None => match l.unit {
            LengthUnit::Percent => {
                let Some((w, h)) = viewport else {
                    return Err(Unresolved::Unconvertible(
                        "a percentage with no viewport size to be a percentage of",
                    ));
                };
                let of = match axis {
                    Axis::Width => w,
                    Axis::Height => h,
                    Axis::Diagonal => ((w * w + h * h) / 2.0).sqrt(),
                };
                l.number / 100.0 * of
            }
            _ => {
                return Err(Unresolved::Unconvertible(
                    "em and ex are sizes of the font, which the importer does not read",
                ))
            }
        },
    };
    if v.is_finite() {
        Ok(v)
    } else {
        Err(Unresolved::Malformed(
            "the length overflows f64 in user units".into(),
        ))
    }
}

/// A length in CSS px when its unit is absolute (none, px, in, cm, mm, pt, pc).
pub(crate) fn absolute(l: &Length) -> Option<f64> {
    let unit = match l.unit {
        LengthUnit::None | LengthUnit::Px => Unit::Pixel,
        LengthUnit::In => Unit::Inch,
        LengthUnit::Cm => Unit::Centimetre,
        LengthUnit::Mm => Unit::Millimetre,
        LengthUnit::Pt => Unit::Point,
        LengthUnit::Pc => Unit::Pica,
        LengthUnit::Em | LengthUnit::Ex | LengthUnit::Percent => return None,
    };
    Some(l.number * unit.in_px())
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    fn ok(text: &str, axis: Axis, viewport: Option<(f64, f64)>) -> f64 {
        match user_units(text, axis, viewport) {
            Ok(v) => v,
            Err(e) => panic!("{text}: {e:?}"),
        }
    }

    #[test]
    fn absolute_units_convert_at_96_px_per_inch() {
        let w = Axis::Width;
        assert_relative_eq!(ok("1in", w, None), 96.0);
        assert_relative_eq!(ok("25.4mm", w, None), 96.0, max_relative = 1e-15);
        assert_relative_eq!(ok("2.54cm", w, None), 96.0, max_relative = 1e-15);
        assert_relative_eq!(ok("72pt", w, None), 96.0, max_relative = 1e-15);
        assert_relative_eq!(ok("6pc", w, None), 96.0, max_relative = 1e-15);
        assert_relative_eq!(ok("3px", w, None), 3.0);
        assert_relative_eq!(ok("-3", w, None), -3.0);
    }

    #[test]
    fn percentages_are_of_the_viewport_side_or_its_normalised_diagonal() {
        let vp = Some((200.0, 100.0));
        assert_relative_eq!(ok("50%", Axis::Width, vp), 100.0);
        assert_relative_eq!(ok("50%", Axis::Height, vp), 50.0);
        // √((200² + 100²)/2) = √25000.
        assert_relative_eq!(ok("100%", Axis::Diagonal, vp), 25_000f64.sqrt());
        assert!(matches!(
            user_units("50%", Axis::Width, None),
            Err(Unresolved::Unconvertible(_))
        ));
    }

    #[test]
    fn font_relative_and_unreadable_lengths_are_refused() {
        assert!(matches!(
            user_units("2em", Axis::Width, None),
            Err(Unresolved::Unconvertible(_))
        ));
        for bad in ["10furlong", "mm", "", "1e999mm", "NaN"] {
            assert!(
                matches!(
                    user_units(bad, Axis::Width, None),
                    Err(Unresolved::Malformed(_))
                ),
                "{bad}"
            );
        }
        // A number that fits f64 but not once converted.
        assert!(matches!(
            user_units("1e307in", Axis::Width, None),
            Err(Unresolved::Malformed(_))
        ));
    }
}
