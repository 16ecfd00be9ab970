//! The sketch an import builds: paths go in one at a time (segments to entities, joins to
//! constraints), with every segment or join left out or held loosely listed as skipped.

use camber_sketch::{Entity, Sketch};

use super::affine::Affine;
use super::build::{build, Outcome};
use super::commands::{subpaths, Segment, Subpath};
use super::ellipse_map::map_ellipse;
use super::errors::{Error, Item};
use super::joins::{join, Placed};
use super::options::{Orientation, SvgOptions};
use crate::Imported;
use crate::Skipped;

/// An import under way.
pub(crate) struct Builder<'a> {
    sketch: Sketch,
    skipped: Vec<Skipped>,
    options: &'a SvgOptions,
    /// Drawing segments read so far, against [`SvgOptions::max_segments`].
    segments: usize,
}

impl<'a> Builder<'a> {
    pub(crate) fn new(options: &'a SvgOptions) -> Self {
        Self {
            sketch: Sketch::new(),
            skipped: Vec::new(),
            options,
            segments: 0,
        }
    }

    pub(crate) fn finish(self) -> Imported {
        Imported {
            sketch: self.sketch,
            skipped: self.skipped,
        }
    }

    /// Lists an item left out.
    pub(crate) fn skip(&mut self, location: String, reason: String) {
        self.skipped.push(Skipped { location, reason });
    }

    /// The map from user coordinates under the transform `ctm` to the sketch's frame.
    pub(crate) fn to_sketch(&self, ctm: &Affine) -> Affine {
        match self.options.orientation {
            Orientation::Upright => Affine::flip_y().then_inner(ctm),
            Orientation::Raw => *ctm,
        }
    }

    /// Counts `n` drawing segments of a shape against the budget.
    pub(crate) fn count(&mut self, item: &Item, n: usize) -> Result<(), Error> {
        self.segments = self.segments.saturating_add(n);
        if self.segments > self.options.max_segments {
            return Err(Error::TooManySegments {
                item: item.clone(),
                command: 0,
                max: self.options.max_segments,
            });
        }
        Ok(())
    }

    /// Adds the path of `commands` drawn under the transform `ctm`.
    ///
    /// # Errors
    /// Those of reading the commands ([`subpaths`]); [`Error::Sketch`] if the sketch refuses a
    /// constraint.
    pub(crate) fn add_path<I>(
        &mut self,
        item: &Item,
        commands: I,
        ctm: &Affine,
    ) -> Result<(), Error>
    where
        I: IntoIterator<Item = Result<svgtypes::PathSegment, svgtypes::Error>>,
    {
        let subs = subpaths(item, commands, self.options.max_segments, self.segments)?;
        self.segments += subs.iter().map(|s| s.segments.len()).sum::<usize>();
        let map = self.to_sketch(ctm);
        for sub in &subs {
            self.add_subpath(item, sub, &map)?;
        }
        Ok(())
    }

    fn add_subpath(&mut self, item: &Item, sub: &Subpath, map: &Affine) -> Result<(), Error> {
        let mut placed: Vec<(Placed, &Segment)> = Vec::new();
        for seg in &sub.segments {
            let where_ = format!("{item}, command {} ({})", seg.command, seg.letter);
            let built = match build(&seg.shape, map, self.options.length_tolerance) {
                Outcome::Skipped(reason) => {
                    self.skip(where_, reason);
                    continue;
                }
                Outcome::Built(b) => b,
            };
            let id = match self.sketch.add_entity(built.entity.clone()) {
                Ok(id) => id,
                Err(e) => {
                    self.skip(
                        where_,
                        format!("the sketch refused its {}: {e}", built.entity.kind_name()),
                    );
                    continue;
                }
            };
            if let Some(note) = built.note {
                self.skip(where_, note);
            }
            let p = Placed {
                id,
                entity: built.entity,
                reversed: built.reversed,
            };
            if let Some((prev, prev_seg)) = placed.last() {
                let (prev, prev_seg) = (prev.clone(), *prev_seg);
                self.add_join(item, (&prev, prev_seg), (&p, seg))?;
            }
            placed.push((p, seg));
        }
        if sub.closed {
            if let (Some((last, last_seg)), Some((first, first_seg))) =
                (placed.last(), placed.first())
            {
                let (last, last_seg) = (last.clone(), *last_seg);
                let (first, first_seg) = (first.clone(), *first_seg);
                self.add_join(item, (&last, last_seg), (&first, first_seg))?;
            }
        }
        Ok(())
    }

    /// The constraints of a join, when the two segments meet (a segment skipped for another
    /// reason than its length may leave a gap, which is not closed).
    fn add_join(
        &mut self,
        item: &Item,
        (first, first_seg): (&Placed, &Segment),
        (second, second_seg): (&Placed, &Segment),
    ) -> Result<(), Error> {
        let (Some(p), Some(q)) = (first.path_point(true), second.path_point(false)) else {
            return Ok(());
        };
        if (p - q).norm() > self.options.length_tolerance {
            return Ok(());
        }
        let j = join(first, second, self.options.tangent_tolerance);
        for c in j.constraints {
            self.sketch
                .add_constraint(c)
                .map_err(|cause| Error::Sketch {
                    item: item.clone(),
                    command: second_seg.command,
                    cause: Box::new(cause),
                })?;
        }
        if let Some(note) = j.note {
            self.skip(
                format!(
                    "{item}, join of commands {} ({}) and {} ({})",
                    first_seg.command, first_seg.letter, second_seg.command, second_seg.letter
                ),
                note,
            );
        }
        Ok(())
    }

    /// Adds the whole ellipse c + R(φ)·diag(rx, ry)·(cos θ, sin θ) drawn under `ctm`: a circle
    /// entity when its image is round, an ellipse entity otherwise.
    pub(crate) fn add_ellipse(
        &mut self,
        item: &Item,
        centre: nalgebra::Point2<f64>,
        rx: f64,
        ry: f64,
        ctm: &Affine,
    ) -> Result<(), Error> {
        self.count(item, 1)?;
        let map = self.to_sketch(ctm);
        let Some(e) = map_ellipse(&map, centre, rx, ry, 0.0) else {
            self.skip(
                item.to_string(),
                "its transformed ellipse is degenerate or out of range".into(),
            );
            return Ok(());
        };
        let entity = if e.is_circle() {
            Entity::Circle {
                center: e.centre,
                radius: e.a,
            }
        } else {
            Entity::Ellipse {
                points: [e.centre, e.centre + e.a_axis * e.a],
                semi_axis_b: e.b,
            }
        };
        if let Err(err) = self.sketch.add_entity(entity) {
            self.skip(item.to_string(), format!("the sketch refused it: {err}"));
        }
        Ok(())
    }
}
