//! Path commands to absolute segments: the SVG path grammar's meaning (not its syntax, which
//! svgtypes reads). Relative coordinates are offsets from the current point at the start of
//! their command; `H`/`V` keep the other coordinate; `S` reflects the previous `C`/`S` second
//! control point about the current point (else uses the current point), `T` the previous
//! `Q`/`T` control point likewise; `Z` draws a line back to the subpath's start when the pen
//! is elsewhere, and a command after `Z` that is not a move starts a new subpath there.
//!
//! Each segment keeps the index of the command that drew it (counting every command from 0,
//! implicit repeats included) and its letter, for error and skip messages.

use nalgebra::Point2;
use svgtypes::PathSegment;

use super::arc::EndpointArc;
use super::errors::{Error, Item};

/// One drawing segment in absolute user coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Shape {
    /// A straight line.
    Line([Point2<f64>; 2]),
    /// A quadratic Bézier curve.
    Quadratic([Point2<f64>; 3]),
    /// A cubic Bézier curve.
    Cubic([Point2<f64>; 4]),
    /// An elliptical arc in its endpoint form.
    Arc(EndpointArc),
}

/// A segment and the command that drew it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Segment {
    /// The command's index in its path (from 0).
    pub(crate) command: usize,
    /// The command's letter as written (`l`, `C`, …; `Z`/`z` for a closing line).
    pub(crate) letter: char,
    /// What it draws.
    pub(crate) shape: Shape,
}

/// The segments of one subpath, and whether `Z` closed it.
#[derive(Debug, Clone, Default, PartialEq)]
pub(crate) struct Subpath {
    /// The segments in drawing order.
    pub(crate) segments: Vec<Segment>,
    /// Whether a `Z` closed it.
    pub(crate) closed: bool,
}

/// The pen state between commands.
struct Pen {
    current: Point2<f64>,
    start: Point2<f64>,
    /// The previous command's last control point, for `S` (after `C`/`S`) and `T` (after `Q`/`T`).
    cubic_control: Option<Point2<f64>>,
    quadratic_control: Option<Point2<f64>>,
}

/// The subpaths of a sequence of parsed commands, in absolute coordinates.
///
/// # Errors
/// [`Error::MalformedPath`] for a command svgtypes refuses, [`Error::NonFinite`] for a
/// coordinate that is not finite or a point that overflows, [`Error::TooManySegments`] beyond
/// `max_segments` drawing segments in all (`already` are counted before this path).
pub(crate) fn subpaths<I>(
    item: &Item,
    commands: I,
    max_segments: usize,
    already: usize,
) -> Result<Vec<Subpath>, Error>
where
    I: IntoIterator<Item = Result<PathSegment, svgtypes::Error>>,
{
    let mut out: Vec<Subpath> = Vec::new();
    let mut pen: Option<Pen> = None;
    let mut open = false;
    let mut count = already;
    for (index, command) in commands.into_iter().enumerate() {
        let command = command.map_err(|e| Error::MalformedPath {
            item: item.clone(),
            command: index,
            message: e.to_string(),
        })?;
        let letter = char::from(command.command());
        check_numbers(item, index, letter, &command)?;
        let point = |p: Point2<f64>| finite_point(item, index, letter, p);
        let rel = !command.is_abs();
        let origin = match (&pen, rel) {
            (Some(p), true) => p.current,
            _ => Point2::origin(),
        };
        let at = |x: f64, y: f64| point(Point2::new(origin.x + x, origin.y + y));
        if let PathSegment::MoveTo { x, y, .. } = command {
            let p = at(x, y)?;
            pen = Some(Pen {
                current: p,
                start: p,
                cubic_control: None,
                quadratic_control: None,
            });
            open = false;
            continue;
        }
        let Some(state) = pen.as_mut() else {
            return Err(Error::MalformedPath {
                item: item.clone(),
                command: index,
                message: format!("the path starts with {letter}, not a move (M or m)"),
            });
        };
        if !open {
            out.push(Subpath::default());
            open = true;
        }
        let from = state.current;
        let mut cubic_control = None;
        let mut quadratic_control = None;
        let shape = match command {
            PathSegment::MoveTo { .. } => continue,
            PathSegment::LineTo { x, y, .. } => Some(Shape::Line([from, at(x, y)?])),
            PathSegment::HorizontalLineTo { x, .. } => Some(Shape::Line([
                from,
                point(Point2::new(origin.x + x, from.y))?,
            ])),
            PathSegment::VerticalLineTo { y, .. } => Some(Shape::Line([
                from,
                point(Point2::new(from.x, origin.y + y))?,
            ])),
            PathSegment::CurveTo {
                x1,
                y1,
                x2,
                y2,
                x,
                y,
                ..
            } => {
                let (c1, c2, to) = (at(x1, y1)?, at(x2, y2)?, at(x, y)?);
                cubic_control = Some(c2);
                Some(Shape::Cubic([from, c1, c2, to]))
            }
            PathSegment::SmoothCurveTo { x2, y2, x, y, .. } => {
                let c1 = match state.cubic_control {
                    Some(c) => point(from + (from - c))?,
                    None => from,
                };
                let (c2, to) = (at(x2, y2)?, at(x, y)?);
                cubic_control = Some(c2);
                Some(Shape::Cubic([from, c1, c2, to]))
            }
            PathSegment::Quadratic { x1, y1, x, y, .. } => {
                let (c, to) = (at(x1, y1)?, at(x, y)?);
                quadratic_control = Some(c);
                Some(Shape::Quadratic([from, c, to]))
            }
            PathSegment::SmoothQuadratic { x, y, .. } => {
                let c = match state.quadratic_control {
                    Some(c) => point(from + (from - c))?,
                    None => from,
                };
                quadratic_control = Some(c);
                Some(Shape::Quadratic([from, c, at(x, y)?]))
            }
            PathSegment::EllipticalArc {
                rx,
                ry,
                x_axis_rotation,
                large_arc,
                sweep,
                x,
                y,
                ..
            } => Some(Shape::Arc(EndpointArc {
                from,
                to: at(x, y)?,
                rx,
                ry,
                rotation_degrees: x_axis_rotation,
                large_arc,
                sweep,
            })),
            PathSegment::ClosePath { .. } => {
                let back = (from != state.start).then_some(Shape::Line([from, state.start]));
                if let Some(last) = out.last_mut() {
                    last.closed = true;
                }
                open = false;
                back
            }
        };
        state.cubic_control = cubic_control;
        state.quadratic_control = quadratic_control;
        if let Some(shape) = shape {
            count += 1;
            if count > max_segments {
                return Err(Error::TooManySegments {
                    item: item.clone(),
                    command: index,
                    max: max_segments,
                });
            }
            state.current = end_of(&shape);
            if let Some(sub) = out.last_mut() {
                sub.segments.push(Segment {
                    command: index,
                    letter,
                    shape,
                });
            }
        }
        if !open {
            state.current = state.start;
        }
    }
    Ok(out)
}

/// The segment's last point.
fn end_of(shape: &Shape) -> Point2<f64> {
    match shape {
        Shape::Line([_, p]) | Shape::Quadratic([_, _, p]) | Shape::Cubic([_, _, _, p]) => *p,
        Shape::Arc(a) => a.to,
    }
}

/// Refuses a command with a number that is not finite (svgtypes already refuses them; kept
/// so that commands built from other sources, such as a shape's attributes, are checked too).
fn check_numbers(
    item: &Item,
    command: usize,
    letter: char,
    segment: &PathSegment,
) -> Result<(), Error> {
    let mut list = [("x", 0.0); 7];
    let n = match *segment {
        PathSegment::MoveTo { x, y, .. }
        | PathSegment::LineTo { x, y, .. }
        | PathSegment::SmoothQuadratic { x, y, .. } => {
            list[..2].copy_from_slice(&[("x", x), ("y", y)]);
            2
        }
        PathSegment::HorizontalLineTo { x, .. } => {
            list[0] = ("x", x);
            1
        }
        PathSegment::VerticalLineTo { y, .. } => {
            list[0] = ("y", y);
            1
        }
        PathSegment::CurveTo {
            x1,
            y1,
            x2,
            y2,
            x,
            y,
            ..
        } => {
            list[..6].copy_from_slice(&[
                ("x1", x1),
                ("y1", y1),
                ("x2", x2),
                ("y2", y2),
                ("x", x),
                ("y", y),
            ]);
            6
        }
        PathSegment::SmoothCurveTo { x2, y2, x, y, .. } => {
            list[..4].copy_from_slice(&[("x2", x2), ("y2", y2), ("x", x), ("y", y)]);
            4
        }
        PathSegment::Quadratic { x1, y1, x, y, .. } => {
            list[..4].copy_from_slice(&[("x1", x1), ("y1", y1), ("x", x), ("y", y)]);
            4
        }
        PathSegment::EllipticalArc {
            rx,
            ry,
            x_axis_rotation,
            x,
            y,
            ..
        } => {
            list[..5].copy_from_slice(&[
                ("rx", rx),
                ("ry", ry),
                ("x-axis-rotation", x_axis_rotation),
                ("x", x),
                ("y", y),
            ]);
            5
        }
        PathSegment::ClosePath { .. } => 0,
    };
    match list[..n].iter().find(|(_, v)| !v.is_finite()) {
        Some((what, value)) => Err(Error::NonFinite {
            item: item.clone(),
            command,
            letter,
            what,
            value: *value,
        }),
        None => Ok(()),
    }
}

/// The point, or [`Error::NonFinite`] when a sum overflowed.
fn finite_point(
    item: &Item,
    command: usize,
    letter: char,
    p: Point2<f64>,
) -> Result<Point2<f64>, Error> {
    for (what, value) in [("x", p.x), ("y", p.y)] {
        if !value.is_finite() {
            return Err(Error::NonFinite {
                item: item.clone(),
                command,
                letter,
                what,
                value,
            });
        }
    }
    Ok(p)
}
