//! A tiny SVG writer in model coordinates.
//!
//! The picture's viewBox is a bounding box of the model grown by a margin; y points up in the
//! model and down in SVG, so every y is negated on output (text therefore stays upright). Stroke
//! widths, point radii and font sizes are given in multiples of a *unit*, 1/400 of the larger
//! side of the box, so pictures look alike at any model size. The SVG coordinates are the model
//! ones scaled so that one unit is one SVG user unit (renderers hint tiny fonts badly).

use std::fmt::Write as _;

use nalgebra::Point2;

/// An axis-aligned box in model coordinates; empty until a point is added.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BBox {
    /// Lower-left corner (smallest x and y).
    pub min: Point2<f64>,
    /// Upper-right corner (largest x and y).
    pub max: Point2<f64>,
}

impl Default for BBox {
    fn default() -> Self {
        Self::empty()
    }
}

impl BBox {
    /// The empty box (min = +∞, max = −∞), which [`include`](Self::include) grows.
    pub fn empty() -> Self {
        Self {
            min: Point2::new(f64::INFINITY, f64::INFINITY),
            max: Point2::new(f64::NEG_INFINITY, f64::NEG_INFINITY),
        }
    }

    /// Grows the box to contain `p`; non-finite points are ignored.
    pub fn include(&mut self, p: Point2<f64>) {
        if p.x.is_finite() && p.y.is_finite() {
            self.min = self.min.inf(&p);
            self.max = self.max.sup(&p);
        }
    }

    /// The box of some points.
    pub fn of(points: impl IntoIterator<Item = Point2<f64>>) -> Self {
        let mut b = Self::empty();
        points.into_iter().for_each(|p| b.include(p));
        b
    }

    /// True until a finite point has been included.
    pub fn is_empty(&self) -> bool {
        self.min.x > self.max.x
    }

    /// Width and height (0 for an empty box).
    pub fn size(&self) -> (f64, f64) {
        if self.is_empty() {
            (0.0, 0.0)
        } else {
            (self.max.x - self.min.x, self.max.y - self.min.y)
        }
    }
}

/// How an element is drawn: colour, width in units, optional fill and dashes.
#[derive(Debug, Clone, PartialEq)]
pub struct Style {
    /// Stroke colour (any SVG colour), or `none`.
    pub stroke: String,
    /// Stroke width in units (see the module docs).
    pub width: f64,
    /// Fill colour; `None` is no fill.
    pub fill: Option<String>,
    /// Dashed stroke.
    pub dashed: bool,
}

impl Style {
    /// A solid stroke of `width` units in `colour`, unfilled.
    pub fn stroke(colour: &str, width: f64) -> Self {
        Self {
            stroke: colour.to_owned(),
            width,
            fill: None,
            dashed: false,
        }
    }

    /// A filled shape without outline.
    pub fn filled(colour: &str) -> Self {
        Self {
            stroke: "none".to_owned(),
            width: 0.0,
            fill: Some(colour.to_owned()),
            dashed: false,
        }
    }

    /// The same style, dashed.
    pub fn with_dashes(mut self) -> Self {
        self.dashed = true;
        self
    }
}

/// Text anchoring along x.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Anchor {
    /// The text starts at the point.
    Start,
    /// The text is centred on the point.
    Middle,
    /// The text ends at the point.
    End,
}

/// An SVG document being written; finish it with [`Svg::finish`].
#[derive(Debug, Clone)]
pub struct Svg {
    /// viewBox origin and size in SVG coordinates (y already flipped and scaled).
    view: [f64; 4],
    /// One unit in model lengths.
    unit: f64,
    /// SVG user units per model unit (1 / `unit`).
    scale: f64,
    body: String,
}

impl Svg {
    /// A picture showing `bbox` with a margin of `margin` times its larger side on every side.
    /// An empty box shows [−1, 1]²; a flat one gets a height (or width) of its larger side; a
    /// box that is (nearly) a single point gets a side of its distance from the origin (at
    /// least 1), so the point sits in the middle of an ordinary picture. Everything is computed
    /// with half sizes, so boxes out to ±f64::MAX still give finite numbers.
    pub fn new(bbox: BBox, margin: f64) -> Self {
        let (min, max) = if bbox.is_empty() {
            (Point2::new(-1.0, -1.0), Point2::new(1.0, 1.0))
        } else {
            (bbox.min, bbox.max)
        };
        // Half sizes and the centre: finite even when max − min would overflow.
        let (hw, hh) = (max.x / 2.0 - min.x / 2.0, max.y / 2.0 - min.y / 2.0);
        let (cx, cy) = (min.x / 2.0 + max.x / 2.0, min.y / 2.0 + max.y / 2.0);
        let reach = cx.abs().max(cy.abs()).max(1.0);
        let mut half = hw.max(hh);
        if half <= 1e-9 * reach {
            half = reach / 2.0;
        }
        // A degenerate side is widened around its middle so the picture is not a line.
        let (hw, hh) = (hw.max(half * 1e-3), hh.max(half * 1e-3));
        let pad = margin.clamp(0.0, 1.0) * half * 2.0;
        let unit = half / 200.0;
        let scale = 200.0 / half;
        let view = [
            cx * scale - (hw * scale + pad * scale),
            -(cy * scale) - (hh * scale + pad * scale),
            2.0 * (hw * scale + pad * scale),
            2.0 * (hh * scale + pad * scale),
        ];
        Self {
            view,
            unit,
            scale,
            body: String::new(),
        }
    }

    /// The length of one unit in model coordinates.
    pub fn unit(&self) -> f64 {
        self.unit
    }

    /// The viewBox as (x, y, width, height) in SVG coordinates.
    pub fn view_box(&self) -> [f64; 4] {
        self.view
    }

    /// SVG user units per model unit: SVG x = `scale`·x, SVG y = −`scale`·y.
    pub fn scale(&self) -> f64 {
        self.scale
    }

    fn sx(&self, x: f64) -> String {
        num(x * self.scale)
    }

    fn sy(&self, y: f64) -> String {
        num(-y * self.scale)
    }

    fn style_attrs(&self, s: &Style) -> String {
        let mut a = format!(
            r#"fill="{}" stroke="{}" stroke-width="{}""#,
            s.fill.as_deref().unwrap_or("none"),
            s.stroke,
            num(s.width)
        );
        if s.dashed {
            let d = 4.0 * s.width.max(0.5);
            let _ = write!(a, r#" stroke-dasharray="{} {}""#, num(d), num(d));
        }
        a
    }

    /// A polyline through the points (nothing for fewer than two).
    pub fn polyline(&mut self, points: &[Point2<f64>], style: &Style) {
        if points.len() < 2 {
            return;
        }
        let coords: Vec<String> = points
            .iter()
            .map(|p| format!("{},{}", self.sx(p.x), self.sy(p.y)))
            .collect();
        let attrs = self.style_attrs(style);
        let _ = writeln!(
            self.body,
            r#"<polyline points="{}" {attrs} stroke-linejoin="round"/>"#,
            coords.join(" ")
        );
    }

    /// A line segment from `a` to `b`.
    pub fn line(&mut self, a: Point2<f64>, b: Point2<f64>, style: &Style) {
        let attrs = self.style_attrs(style);
        let _ = writeln!(
            self.body,
            r#"<line x1="{}" y1="{}" x2="{}" y2="{}" {attrs}/>"#,
            self.sx(a.x),
            self.sy(a.y),
            self.sx(b.x),
            self.sy(b.y)
        );
    }

    /// A circle of model radius `radius`.
    pub fn circle(&mut self, center: Point2<f64>, radius: f64, style: &Style) {
        let attrs = self.style_attrs(style);
        let _ = writeln!(
            self.body,
            r#"<circle cx="{}" cy="{}" r="{}" {attrs}/>"#,
            self.sx(center.x),
            self.sy(center.y),
            num(radius * self.scale)
        );
    }

    /// A circular arc, as the path's elliptical-arc command (exact: no samples). The model's
    /// counter-clockwise sweep is SVG's negative-angle direction (its y axis points down), so
    /// the sweep flag is 0; the large-arc flag is set for sweeps above π.
    pub fn arc(&mut self, arc: &camber_geom::CircularArc<f64>, style: &Style) {
        let attrs = self.style_attrs(style);
        let (a, b) = (arc.start_point(), arc.end_point());
        let r = num(arc.radius() * self.scale);
        let large = u8::from(arc.sweep() > std::f64::consts::PI);
        let _ = writeln!(
            self.body,
            r#"<path d="M {} {} A {r} {r} 0 {large} 0 {} {}" {attrs}/>"#,
            self.sx(a.x),
            self.sy(a.y),
            self.sx(b.x),
            self.sy(b.y)
        );
    }

    /// An ellipse, exact: SVG's `ellipse` rotated by −θ (its y axis points down, so the
    /// model's counter-clockwise rotation is SVG's clockwise one).
    pub fn ellipse(&mut self, e: &camber_geom::Ellipse<f64>, style: &Style) {
        let attrs = self.style_attrs(style);
        let (cx, cy) = (self.sx(e.center().x), self.sy(e.center().y));
        let _ = writeln!(
            self.body,
            r#"<ellipse cx="{cx}" cy="{cy}" rx="{}" ry="{}" transform="rotate({} {cx} {cy})" {attrs}/>"#,
            num(e.semi_axis_a() * self.scale),
            num(e.semi_axis_b() * self.scale),
            num(-e.rotation().to_degrees()),
        );
    }

    /// An elliptic arc, as the path's elliptical-arc command (exact): radii a, b, x-axis
    /// rotation −θ in degrees, sweep flag 0 (the model's counter-clockwise run), large-arc
    /// flag for parametric sweeps above π (SVG measures the sweep on the ellipse scaled to a
    /// circle, which is the parametric angle).
    pub fn elliptic_arc(&mut self, arc: &camber_geom::EllipticArc<f64>, style: &Style) {
        let attrs = self.style_attrs(style);
        let (p, q) = (arc.start_point(), arc.end_point());
        let e = arc.ellipse();
        let large = u8::from(arc.sweep() > std::f64::consts::PI);
        let _ = writeln!(
            self.body,
            r#"<path d="M {} {} A {} {} {} {large} 0 {} {}" {attrs}/>"#,
            self.sx(p.x),
            self.sy(p.y),
            num(e.semi_axis_a() * self.scale),
            num(e.semi_axis_b() * self.scale),
            num(-e.rotation().to_degrees()),
            self.sx(q.x),
            self.sy(q.y)
        );
    }

    /// A dot marking a point: a filled circle of `radius_units` units.
    pub fn dot(&mut self, p: Point2<f64>, radius_units: f64, colour: &str) {
        self.circle(p, radius_units * self.unit, &Style::filled(colour));
    }

    /// Text at `at`, `size_units` units high, upright.
    pub fn text(
        &mut self,
        at: Point2<f64>,
        text: &str,
        size_units: f64,
        anchor: Anchor,
        colour: &str,
    ) {
        let anchor = match anchor {
            Anchor::Start => "start",
            Anchor::Middle => "middle",
            Anchor::End => "end",
        };
        let _ = writeln!(
            self.body,
            r#"<text x="{}" y="{}" font-size="{}" text-anchor="{anchor}" fill="{colour}">{}</text>"#,
            self.sx(at.x),
            self.sy(at.y),
            num(size_units),
            escape(text)
        );
    }

    /// The complete document, white background first.
    pub fn finish(self) -> String {
        let [x, y, w, h] = self.view;
        let (pw, ph) = if w >= h {
            (800.0, 800.0 * h / w)
        } else {
            (800.0 * w / h, 800.0)
        };
        format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"{} {} {} {}\" width=\"{}\" height=\"{}\" font-family=\"sans-serif\">\n\
             <rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"white\"/>\n{}</svg>\n",
            num(x),
            num(y),
            num(w),
            num(h),
            num(pw),
            num(ph),
            num(x),
            num(y),
            num(w),
            num(h),
            self.body
        )
    }
}

/// A number with enough digits for a picture and no trailing noise.
fn num(v: f64) -> String {
    let s = format!("{v:.6}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".to_owned()
    } else {
        s.to_owned()
    }
}

/// Escapes the XML special characters of text content.
fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn view_box_has_margin_and_flips_y() {
        let b = BBox::of([Point2::new(0.0, 0.0), Point2::new(4.0, 2.0)]);
        let svg = Svg::new(b, 0.25);
        let [x, y, w, h] = svg.view_box();
        // Model box [-1, 5] × [-1, 3], flipped to y ∈ [-3, 1], at 100 SVG units per model unit.
        assert!((svg.unit() - 0.01).abs() < 1e-15 && (svg.scale() - 100.0).abs() < 1e-9);
        assert!((x + 100.0).abs() < 1e-9 && (y + 300.0).abs() < 1e-9);
        assert!((w - 600.0).abs() < 1e-9 && (h - 400.0).abs() < 1e-9);
    }

    #[test]
    fn elements_are_written_with_flipped_y() {
        let mut svg = Svg::new(
            BBox::of([Point2::new(0.0, 0.0), Point2::new(1.0, 1.0)]),
            0.1,
        );
        svg.line(
            Point2::new(0.0, 0.5),
            Point2::new(1.0, 1.0),
            &Style::stroke("black", 1.0),
        );
        svg.text(Point2::new(0.0, 0.25), "a<b", 10.0, Anchor::Start, "black");
        let doc = svg.finish();
        assert!(doc.contains(r#"y1="-200""#), "{doc}");
        assert!(doc.contains("a&lt;b"));
        assert!(doc.ends_with("</svg>\n"));
    }

    /// A quarter arc about the origin from +x to +y, at 200 SVG units per model unit: from
    /// (200, 0) to (0, −200) on screen, small and in SVG's negative-angle direction; a sweep
    /// above π sets the large-arc flag.
    #[test]
    fn arcs_are_exact_path_arcs_turning_the_model_way() {
        use std::f64::consts::FRAC_PI_2;
        let bbox = BBox::of([Point2::new(-1.0, -1.0), Point2::new(1.0, 1.0)]);
        let mut svg = Svg::new(bbox, 0.0);
        let quarter =
            camber_geom::CircularArc::try_new(Point2::origin(), 1.0, 0.0, FRAC_PI_2).unwrap();
        svg.arc(&quarter, &Style::stroke("black", 1.0));
        let big =
            camber_geom::CircularArc::try_new(Point2::origin(), 1.0, 0.0, -FRAC_PI_2).unwrap();
        svg.arc(&big, &Style::stroke("black", 1.0));
        let doc = svg.finish();
        assert!(
            doc.contains(r#"d="M 200 0 A 200 200 0 0 0 0 -200""#),
            "{doc}"
        );
        assert!(
            doc.contains(r#"d="M 200 0 A 200 200 0 1 0 0 200""#),
            "{doc}"
        );
    }

    #[test]
    fn ellipses_are_exact_elements_and_path_arcs_turning_the_model_way() {
        use std::f64::consts::FRAC_PI_2;
        let bbox = BBox::of([Point2::new(-1.0, -1.0), Point2::new(1.0, 1.0)]);
        let mut svg = Svg::new(bbox, 0.0);
        let upright = camber_geom::Ellipse::try_new(Point2::origin(), 1.0, 0.5, FRAC_PI_2).unwrap();
        svg.ellipse(&upright, &Style::stroke("black", 1.0));
        let flat = camber_geom::Ellipse::try_new(Point2::origin(), 1.0, 0.5, 0.0).unwrap();
        svg.elliptic_arc(
            &flat.arc(0.0, FRAC_PI_2).unwrap(),
            &Style::stroke("black", 1.0),
        );
        svg.elliptic_arc(
            &flat.arc(0.0, -FRAC_PI_2).unwrap(),
            &Style::stroke("black", 1.0),
        );
        let doc = svg.finish();
        assert!(
            doc.contains(r#"rx="200" ry="100" transform="rotate(-90 "#),
            "{doc}"
        );
        // From (1, 0) to the top (0, 0.5), a quarter; to the bottom the long way round.
        assert!(
            doc.contains(r#"d="M 200 0 A 200 100 0 0 0 0 -100""#),
            "{doc}"
        );
        assert!(
            doc.contains(r#"d="M 200 0 A 200 100 0 1 0 0 100""#),
            "{doc}"
        );
    }

    #[test]
    fn numbers_are_short() {
        assert_eq!(num(1.0), "1");
        assert_eq!(num(-0.0000001), "0");
        assert_eq!(num(0.125), "0.125");
    }
}
