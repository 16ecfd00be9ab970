//! W8, many variants of one topology: the W2 `bspline7` sketch at its rough start with the three
//! circle radii scaled by factors 1 + 0.1·(u − ½), u drawn from the W5 LCG (seed 12345, three
//! draws per variant: LE, TH, TE).

use nalgebra::Point2;

use camber_sketch::{Entity, Result, Sketch};

use crate::rectangles::Lcg;
use crate::{w2_bspline7, W2, W2_CIRCLES};

/// Three circles (centre, radius): leading edge, thickness, trailing edge.
pub type Circles = [([f64; 2], f64); 3];

/// The circles (centre, radius) of the first `n` W8 variants: W2's circles with each radius
/// scaled by 1 + 0.1·(u − ½), u from the W5 LCG in the order LE, TH, TE per variant.
///
/// ```
/// let circles = camber_workloads::w8_circles(2);
/// let (_, r) = circles[1][2];
/// assert!((r / 0.015 - 1.0).abs() <= 0.05);
/// ```
pub fn w8_circles(n: usize) -> Vec<Circles> {
    let mut rng = Lcg(12_345);
    (0..n)
        .map(|_| W2_CIRCLES.map(|(c, r)| (c, r * (1.0 + 0.1 * (rng.unit() - 0.5)))))
        .collect()
}

/// The first `n` W8 variants: the W2 `bspline7` sketch at its rough start (unsolved) with the
/// circles of [`w8_circles`], each with its circles; the entity ids are those of one W2 sketch
/// in every variant.
///
/// ```
/// let (variants, w) = camber_workloads::w8_variants(3)?;
/// assert_eq!(variants.len(), 3);
/// let (mut s, circles) = variants[0].clone();
/// s.solve()?;
/// assert!(camber_workloads::w2_valid_with(&s, &w, &circles));
/// # Ok::<(), camber_sketch::Error>(())
/// ```
///
/// # Errors
/// None in practice (the radii stay within 5 % of W2's); the signature carries the sketch's
/// errors.
pub fn w8_variants(n: usize) -> Result<(Vec<(Sketch, Circles)>, W2)> {
    let (base, w) = w2_bspline7()?;
    let mut out = Vec::with_capacity(n);
    for circles in w8_circles(n) {
        let mut s = base.clone();
        for (id, (c, r)) in w.circles.iter().zip(circles) {
            s.set_entity(
                *id,
                Entity::Circle {
                    center: Point2::new(c[0], c[1]),
                    radius: r,
                },
            )?;
        }
        out.push((s, circles));
    }
    Ok((out, w))
}
