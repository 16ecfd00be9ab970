//! Whole SVG documents: every `<path>` (and the basic shapes) under the root `<svg>`, each
//! drawn under the `transform` of its ancestors composed from the root inwards with its own,
//! and under the placement of every `svg` viewport it is in.
//!
//! - Groups (`g`, `a`, `switch`) are walked; a nested `svg` places its content by its `x`,
//!   `y`, `width`, `height`, `viewBox` and `preserveAspectRatio` ([`super::placement`]), as
//!   does the root when the sketch is in physical units ([`super::SketchUnits`]).
//! - `path` and the basic shapes are read by [`super::shapes`], their lengths in any absolute
//!   unit or as percentages of their viewport ([`super::units`]).
//! - `use` draws the element its `href` (or `xlink:href`) `#id` references, as a child of the
//!   `use` translated by its `x`, `y`; a `symbol` or an `svg` so drawn is placed as a
//!   viewport of the `use`'s `width` and `height`. A reference leading back to an element it
//!   is drawing is [`Error::ReferenceLoop`]; the elements drawn through references are counted
//!   against [`SvgOptions::max_use_elements`], and their depth against `max_depth`.
//! - `display: none` leaves out an element and its content, `visibility: hidden` a shape
//!   ([`super::style`]); both are listed as skipped.
//! - Definitions (`defs`, `symbol`, `clipPath`, `mask`, `marker`, `pattern`) draw nothing
//!   where they stand: shapes inside one that no `use` references are listed as skipped.
//! - `text`, `image`, `foreignObject` and SVG elements the importer does not know are listed
//!   as skipped, and so is a style sheet (its rules are not applied); elements that draw
//!   nothing (`title`, `desc`, `metadata`, gradients, filters, …) and elements of other
//!   namespaces (an editor's metadata) are passed over without a note.

use std::collections::{HashMap, HashSet};
use std::str::FromStr;

use roxmltree::{Document, Node, NodeId, ParsingOptions};

use super::affine::Affine;
use super::builder::Builder;
use super::errors::{Error, Item};
use super::nesting::{self, Finding};
use super::options::SvgOptions;
use super::placement::{self, Placed};
use super::references::{drawn_through_use, href, References, Target};
use super::shapes::{self, length, malformed, Place};
use super::style;
use super::viewport::translation;
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
                    line: Lines::new(svg_text).of(t.offset),
                },
                depth: t.depth,
                max: options.max_depth,
            })
        }
        Some(Finding::MarkupInDtd { offset }) => {
            return Err(Error::Xml {
                message: format!(
                    "the DTD at line {} could declare elements in its entities, which are not read",
                    Lines::new(svg_text).of(offset)
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
    let lines = Lines::new(svg_text);
    let mut b = Builder::new(options);
    let mut walk = Walk {
        doc: &doc,
        lines: &lines,
        refs: References::new(&doc),
        options,
        use_elements: 0,
        draws: HashMap::new(),
        definitions_listed: HashSet::new(),
        stack: vec![Visit {
            node: root,
            ctm: Affine::identity(),
            depth: 0,
            viewport: None,
            hidden: false,
            chain: None,
            instance: None,
        }],
    };
    // Depth-first in document order with an explicit stack: nesting cannot overflow the
    // call stack, and the depth budget is checked on the way down.
    while let Some(v) = walk.stack.pop() {
        walk.visit(&mut b, v)?;
    }
    Ok(b.finish())
}

/// An element to draw: under its parent's map `ctm` (user units to the sketch's frame, before
/// the y flip), at `depth`, in a viewport of size `viewport` (user units), its parent's
/// shapes `hidden` or not, drawn through the reference chain `chain` (`None` where it stands
/// in the document), and for a `symbol` or `svg` drawn by a `use`, the `use`'s width and
/// height where given.
struct Visit<'a, 'i> {
    node: Node<'a, 'i>,
    ctm: Affine,
    depth: usize,
    viewport: Option<(f64, f64)>,
    hidden: bool,
    chain: Option<usize>,
    instance: Option<(Option<f64>, Option<f64>)>,
}

/// The line starts of the text, for an element's line by a binary search.
struct Lines(Vec<usize>);

impl Lines {
    fn new(text: &str) -> Self {
        Lines(
            text.bytes()
                .enumerate()
                .filter(|(_, c)| *c == b'\n')
                .map(|(k, _)| k)
                .collect(),
        )
    }

    /// The line (from 1) of a byte offset.
    fn of(&self, offset: usize) -> u32 {
        u32::try_from(self.0.partition_point(|&nl| nl < offset) + 1).unwrap_or(u32::MAX)
    }
}

struct Walk<'a, 'i, 'o> {
    doc: &'a Document<'i>,
    lines: &'a Lines,
    refs: References<'a, 'i>,
    options: &'o SvgOptions,
    use_elements: usize,
    /// Whether an element holds something drawn, by element: asked of every `display: none`
    /// element each time a reference draws it, answered once.
    draws: HashMap<NodeId, bool>,
    /// The definitions elements listed already (a reference drawing a group that holds one
    /// would list it again, and count its shapes again, at every instance).
    definitions_listed: HashSet<NodeId>,
    stack: Vec<Visit<'a, 'i>>,
}

impl<'a, 'i> Walk<'a, 'i, '_> {
    fn item(&self, node: &Node<'_, '_>) -> Item {
        Item::Element {
            tag: node.tag_name().name().to_string(),
            id: node.attribute("id").map(str::to_string),
            line: self.lines.of(node.range().start),
        }
    }

    fn visit(&mut self, b: &mut Builder<'_>, v: Visit<'a, 'i>) -> Result<(), Error> {
        let node = v.node;
        let item = self.item(&node);
        if v.depth > self.options.max_depth {
            return Err(Error::TooDeep {
                item,
                depth: v.depth,
                max: self.options.max_depth,
            });
        }
        if v.chain.is_some() {
            self.use_elements += 1;
            if self.use_elements > self.options.max_use_elements {
                return Err(Error::TooManyUseElements {
                    item,
                    max: self.options.max_use_elements,
                });
            }
        }
        let tag = node.tag_name().name();
        if style::display_none(&node) {
            let draws = *self.draws.entry(node.id()).or_insert_with(|| draws(&node));
            if draws {
                b.skip(
                    item.to_string(),
                    "display is none: it and what it holds are not drawn".into(),
                );
            }
            return Ok(());
        }
        let hidden = style::hidden(&node, v.hidden);
        let mut ctm = match node.attribute("transform") {
            Some(t) => v.ctm.then_inner(&transform(&item, t)?),
            None => v.ctm,
        };
        if !ctm.is_finite() {
            return Err(malformed(
                &item,
                "transform",
                node.attribute("transform").unwrap_or(""),
                "the composed transform overflows f64",
            ));
        }
        let mut viewport = v.viewport;
        let descend = match tag {
            "svg" if node == self.doc.root_element() && v.chain.is_none() => {
                let Placed { map, viewport: vp } =
                    placement::root(b, &node, &item, self.options.units)?;
                ctm = ctm.then_inner(&map);
                viewport = vp;
                true
            }
            "svg" | "symbol" if tag == "svg" || v.instance.is_some() => {
                let instance = v.instance.unwrap_or((None, None));
                match placement::nested(b, &node, &item, v.viewport, instance)? {
                    Some(Placed { map, viewport: vp }) => {
                        ctm = ctm.then_inner(&map);
                        if !ctm.is_finite() {
                            return Err(malformed(
                                &item,
                                "viewBox",
                                node.attribute("viewBox").unwrap_or(""),
                                "the composed map overflows f64",
                            ));
                        }
                        viewport = vp;
                        true
                    }
                    None => false,
                }
            }
            "g" | "a" | "switch" => true,
            "use" => {
                self.reference(b, &node, &item, &v, ctm, hidden)?;
                false
            }
            _ if DEFINITIONS.contains(&tag) => {
                let unreferenced = if self.definitions_listed.insert(node.id()) {
                    self.unreferenced_shapes(&node)
                } else {
                    0
                };
                if unreferenced > 0 {
                    b.skip(
                        item.to_string(),
                        format!("definitions are not drawn where they stand; the {unreferenced} shape(s) inside that no <use> references are not imported"),
                    );
                }
                false
            }
            "style" => {
                if node.text().is_some_and(|t| !t.trim().is_empty()) {
                    b.skip(
                        item.to_string(),
                        "style sheets are not read: display and visibility set by its rules are not applied".into(),
                    );
                }
                false
            }
            _ if NOT_DRAWN.contains(&tag) => false,
            _ => {
                if hidden && SHAPES.contains(&tag) {
                    b.skip(
                        item.to_string(),
                        "visibility is hidden, so it is not drawn".into(),
                    );
                } else if det_is_zero(&ctm) && SHAPES.contains(&tag) {
                    b.skip(
                        item.to_string(),
                        "its transform is singular, so SVG draws nothing".into(),
                    );
                } else {
                    let place = Place {
                        item: &item,
                        ctm: &ctm,
                        viewport,
                    };
                    shapes::shape(b, &node, &place)?;
                }
                false
            }
        };
        if descend {
            let children: Vec<Node<'a, 'i>> = node
                .children()
                .filter(|n| n.is_element() && is_svg(n))
                .collect();
            for child in children.into_iter().rev() {
                self.stack.push(Visit {
                    node: child,
                    ctm,
                    depth: v.depth + 1,
                    viewport,
                    hidden,
                    chain: v.chain,
                    instance: None,
                });
            }
        }
        Ok(())
    }

    /// A `use` at `node` (its own transform in `ctm`): the element it references, queued to be
    /// drawn next as its child, translated by its x, y.
    fn reference(
        &mut self,
        b: &mut Builder<'_>,
        node: &Node<'a, 'i>,
        item: &Item,
        v: &Visit<'a, 'i>,
        ctm: Affine,
        hidden: bool,
    ) -> Result<(), Error> {
        let target = match self.refs.target(node) {
            Target::Element(t) => t,
            Target::NotFollowed(why) => {
                b.skip(item.to_string(), why.into());
                return Ok(());
            }
            Target::Missing => {
                b.skip(
                    item.to_string(),
                    format!(
                        "no element has the id it references ({})",
                        href(node)
                            .unwrap_or("")
                            .chars()
                            .take(80)
                            .collect::<String>()
                    ),
                );
                return Ok(());
            }
        };
        if self.refs.loops(node, &target, v.chain) {
            return Err(Error::ReferenceLoop {
                item: item.clone(),
                href: href(node).unwrap_or("").chars().take(80).collect(),
            });
        }
        let target_tag = target.tag_name().name();
        if !drawn_through_use(target_tag) {
            b.skip(
                item.to_string(),
                format!("it references a <{target_tag}>, which is not drawn through a use"),
            );
            return Ok(());
        }
        let mut xy = [0.0; 2];
        let mut size = [None; 2];
        for (k, name) in ["x", "y"].into_iter().enumerate() {
            match length(node, item, name, 0.0, v.viewport)? {
                Ok(l) => xy[k] = l,
                Err(reason) => {
                    b.skip(item.to_string(), format!("{reason}, so it is not drawn"));
                    return Ok(());
                }
            }
        }
        for (k, name) in ["width", "height"].into_iter().enumerate() {
            if node.has_attribute(name) {
                match length(node, item, name, 0.0, v.viewport)? {
                    Ok(l) => size[k] = Some(l),
                    Err(reason) => {
                        b.skip(item.to_string(), format!("{reason}, so it is not drawn"));
                        return Ok(());
                    }
                }
            }
        }
        let at = ctm.then_inner(&translation(xy[0], xy[1]));
        if !at.is_finite() {
            return Err(malformed(
                item,
                "x",
                node.attribute("x").unwrap_or(""),
                "the offset (x, y) under the transform overflows f64",
            ));
        }
        let placed = matches!(target_tag, "symbol" | "svg");
        let chain = self.refs.extend(&target, v.chain);
        self.stack.push(Visit {
            node: target,
            ctm: at,
            depth: v.depth + 1,
            viewport: v.viewport,
            hidden,
            chain: Some(chain),
            instance: placed.then_some((size[0], size[1])),
        });
        Ok(())
    }

    /// The shapes inside a definitions element that are not, nor are inside, an element some
    /// `use` references.
    fn unreferenced_shapes(&self, defs: &Node<'_, '_>) -> usize {
        defs.descendants()
            .filter(|n| n.is_element() && SHAPES.contains(&n.tag_name().name()))
            .filter(|n| {
                !n.ancestors()
                    .take_while(|a| a.id() != defs.id())
                    .any(|a| self.refs.is_referenced(&a))
            })
            .count()
    }
}

/// Whether an element is or holds something that would draw (a shape or a `use`).
fn draws(node: &Node<'_, '_>) -> bool {
    node.descendants()
        .any(|n| n.is_element() && (SHAPES.contains(&n.tag_name().name()) || n.has_tag_name("use")))
}

fn is_svg(node: &Node<'_, '_>) -> bool {
    matches!(node.tag_name().namespace(), None | Some(SVG_NAMESPACE))
}

fn det_is_zero(ctm: &Affine) -> bool {
    ctm.determinant().abs() <= 0.0
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
