//! Random valid paths import without panic, and every segment, sampled, matches the SVG
//! curve worked out independently here (the commands interpreted by the test's own walk,
//! arcs by the geometric construction of `svg_support`).
#![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

mod svg_support;

use camber_interop::svg::{import_path, Orientation, SvgOptions};
use camber_sketch::Entity;
use nalgebra::Point2;
use proptest::prelude::*;
use svg_support::{bezier, entities, max_deviation, p, svg_arc};

/// One command: its letter (upper case), relative or not, and numbers enough for any.
type Command = (usize, bool, [i32; 7]);

const LETTERS: [char; 9] = ['M', 'L', 'H', 'V', 'C', 'S', 'Q', 'T', 'A'];

fn command() -> impl Strategy<Value = Command> {
    (
        0..LETTERS.len() + 1,
        any::<bool>(),
        prop::array::uniform7(-20i32..20),
    )
}

/// The path text and the curves it draws (each a function of t, or `None` for a segment
/// without length), interpreted by the rules of SVG's path grammar.
type Curve = Box<dyn Fn(f64) -> Point2<f64>>;

fn interpret(cmds: &[Command]) -> (String, Vec<Option<Curve>>) {
    let mut text = String::from("M 0 0");
    let (mut cur, mut start) = (p(0.0, 0.0), p(0.0, 0.0));
    let (mut last_c, mut last_q): (Option<Point2<f64>>, Option<Point2<f64>>) = (None, None);
    let mut curves: Vec<Option<Curve>> = Vec::new();
    for &(k, rel, n) in cmds {
        let f: Vec<f64> = n.iter().map(|v| f64::from(*v)).collect();
        let o = if rel { cur } else { p(0.0, 0.0) };
        let at = |i: usize| p(o.x + f[i], o.y + f[i + 1]);
        let (mut nc, mut nq) = (None, None);
        if k == LETTERS.len() {
            text.push_str(if rel { " z" } else { " Z" });
            let seg = (cur != start).then(|| vec![cur, start]);
            cur = start;
            last_c = None;
            last_q = None;
            if let Some(s) = seg {
                curves.push(curve(s));
            }
            continue;
        }
        let letter = if rel {
            LETTERS[k].to_ascii_lowercase()
        } else {
            LETTERS[k]
        };
        let (args, points): (Vec<f64>, Vec<Point2<f64>>) = match LETTERS[k] {
            'M' => {
                cur = at(0);
                start = cur;
                text.push_str(&format!(" {letter} {} {}", f[0], f[1]));
                last_c = None;
                last_q = None;
                continue;
            }
            'L' => (f[..2].to_vec(), vec![cur, at(0)]),
            'H' => (vec![f[0]], vec![cur, p(o.x + f[0], cur.y)]),
            'V' => (vec![f[0]], vec![cur, p(cur.x, o.y + f[0])]),
            'C' => {
                nc = Some(at(2));
                (f[..6].to_vec(), vec![cur, at(0), at(2), at(4)])
            }
            'S' => {
                let c1 = last_c.map_or(cur, |c| cur + (cur - c));
                nc = Some(at(0));
                (f[..4].to_vec(), vec![cur, c1, at(0), at(2)])
            }
            'Q' => {
                nq = Some(at(0));
                (f[..4].to_vec(), vec![cur, at(0), at(2)])
            }
            'T' => {
                let c = last_q.map_or(cur, |c| cur + (cur - c));
                nq = Some(c);
                (f[..2].to_vec(), vec![cur, c, at(0)])
            }
            _ => {
                let (rx, ry, rot) = (f[0], f[1], f[2] * 7.0);
                let (fa, fs) = (n[3] % 2 != 0, n[4] % 2 != 0);
                let to = at(5);
                text.push_str(&format!(
                    " {letter} {rx} {ry} {rot} {} {} {} {}",
                    u8::from(fa),
                    u8::from(fs),
                    f[5],
                    f[6]
                ));
                let from = cur;
                cur = to;
                last_c = None;
                last_q = None;
                if from == to {
                    curves.push(None);
                } else if rx == 0.0 || ry == 0.0 {
                    curves.push(curve(vec![from, to]));
                } else {
                    curves.push(Some(Box::new(svg_arc(from, to, (rx, ry), rot, fa, fs))));
                }
                continue;
            }
        };
        text.push_str(&format!(" {letter}"));
        for a in args {
            text.push_str(&format!(" {a}"));
        }
        cur = *points.last().unwrap();
        last_c = nc;
        last_q = nq;
        curves.push(curve(points));
    }
    (text, curves)
}

fn curve(points: Vec<Point2<f64>>) -> Option<Curve> {
    let first = points[0];
    if points.iter().all(|q| *q == first) {
        return None;
    }
    Some(Box::new(move |t| bezier(&points, t)))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn random_paths_match_their_independent_evaluation(cmds in prop::collection::vec(command(), 1..12)) {
        let (text, curves) = interpret(&cmds);
        let raw = SvgOptions::default().with_orientation(Orientation::Raw);
        let out = import_path(&text, &raw).unwrap();
        let drawn: Vec<&Curve> = curves.iter().flatten().collect();
        let e = entities(&out.sketch);
        prop_assert_eq!(e.len(), drawn.len(), "{}: {:?}", text, out.skipped);
        prop_assert_eq!(out.skipped.iter().filter(|s| !s.location.contains("join")).count(), curves.len() - drawn.len());
        for (entity, svg) in e.iter().zip(drawn) {
            let size = entity.hull_points().iter().fold(1.0_f64, |m, q| m.max(q.coords.amax()));
            // An arc's centre moves as √(1 − Λ) near the half turn Λ = 1 (SVG's radii just
            // reaching both ends), so rounding of 10⁻¹⁶ in Λ moves it by 10⁻⁸ of the radius in
            // either evaluation; lines and Béziers are exact up to rounding.
            let tolerance = if matches!(entity, Entity::Arc(_) | Entity::EllipticArc { .. }) { 1e-7 } else { 1e-12 };
            let dev = max_deviation(entity, svg, |q| q, 64);
            prop_assert!(dev < tolerance * size, "{}: {:?} off by {:e}", text, entity, dev);
        }
    }
}
