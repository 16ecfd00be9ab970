//! `use` references within a document: the elements by `id` (the first of a repeated id, as
//! browsers do), the set of elements some `use` references (so definitions nobody draws can be
//! listed), and the chains of references being drawn, against which a `use` that leads back to
//! an element it is drawing is found.

use std::collections::{HashMap, HashSet};

use roxmltree::{Document, Node, NodeId};

const XLINK_NAMESPACE: &str = "http://www.w3.org/1999/xlink";

/// The reference of a `use`: its `href`, else its `xlink:href`.
pub(crate) fn href<'a>(node: &Node<'a, '_>) -> Option<&'a str> {
    node.attribute("href")
        .or_else(|| node.attribute((XLINK_NAMESPACE, "href")))
}

/// Whether a `use` draws an element of this tag: every element but the definitions other
/// than `symbol` (a `defs`, `clipPath`, `mask`, `marker` or `pattern` draws nothing through a
/// `use`).
pub(crate) fn drawn_through_use(tag: &str) -> bool {
    !matches!(tag, "defs" | "clipPath" | "mask" | "marker" | "pattern")
}

/// Where a reference leads.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Target<'a, 'i> {
    /// The element of that id.
    Element(Node<'a, 'i>),
    /// No `#id` form (another file, or nothing): why, in a phrase.
    NotFollowed(&'static str),
    /// No element has the id.
    Missing,
}

/// A document's ids, its referenced elements and the chains of references being drawn.
pub(crate) struct References<'a, 'i> {
    ids: HashMap<&'a str, Node<'a, 'i>>,
    referenced: HashSet<NodeId>,
    /// Links of the chains: the element a `use` draws and the link of the `use` that drew the
    /// element holding it (`None` at the document's own elements).
    links: Vec<(NodeId, Option<usize>)>,
}

impl<'a, 'i> References<'a, 'i> {
    /// One pass over the document's elements.
    pub(crate) fn new(doc: &'a Document<'i>) -> Self {
        let mut ids = HashMap::new();
        let mut uses = Vec::new();
        for n in doc.descendants().filter(Node::is_element) {
            if let Some(id) = n.attribute("id") {
                ids.entry(id).or_insert(n);
            }
            if n.tag_name().name() == "use" {
                uses.push(n);
            }
        }
        let mut r = Self {
            ids,
            referenced: HashSet::new(),
            links: Vec::new(),
        };
        for u in uses {
            if let Target::Element(t) = r.target(&u) {
                if drawn_through_use(t.tag_name().name()) {
                    r.referenced.insert(t.id());
                }
            }
        }
        r
    }

    /// Where the `use` element `node` leads.
    pub(crate) fn target(&self, node: &Node<'a, 'i>) -> Target<'a, 'i> {
        let Some(h) = href(node) else {
            return Target::NotFollowed("it has no href, so it references nothing");
        };
        let Some(id) = h.trim().strip_prefix('#') else {
            return Target::NotFollowed("references to other files are not followed");
        };
        match self.ids.get(id) {
            Some(n) => Target::Element(*n),
            None => Target::Missing,
        }
    }

    /// Whether some `use` of the document draws `node` itself.
    pub(crate) fn is_referenced(&self, node: &Node<'_, '_>) -> bool {
        self.referenced.contains(&node.id())
    }

    /// Whether drawing `target` for a `use` at `node`, reached through the chain `chain`,
    /// would draw an element already being drawn: `target` holds `node` (or is it), or it is
    /// an element some `use` of the chain draws.
    pub(crate) fn loops(
        &self,
        node: &Node<'_, '_>,
        target: &Node<'_, '_>,
        chain: Option<usize>,
    ) -> bool {
        if node.ancestors().any(|a| a.id() == target.id()) {
            return true;
        }
        let mut link = chain;
        while let Some(k) = link {
            let Some(&(drawn, up)) = self.links.get(k) else {
                return false;
            };
            if drawn == target.id() {
                return true;
            }
            link = up;
        }
        false
    }

    /// The chain `chain` extended by a `use` drawing `target`.
    pub(crate) fn extend(&mut self, target: &Node<'_, '_>, chain: Option<usize>) -> usize {
        self.links.push((target.id(), chain));
        self.links.len() - 1
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

    use super::*;

    #[test]
    fn href_and_xlink_href_lead_to_the_first_element_of_the_id() {
        let doc = Document::parse(
            r##"<svg xmlns:xlink="http://www.w3.org/1999/xlink"><path id="p" d="M 0 0"/><rect id="p"/><use href="#p"/><use xlink:href=" #p"/><use href="other.svg#p"/><use href="#q"/><use/></svg>"##,
        )
        .unwrap();
        let r = References::new(&doc);
        let uses: Vec<Node<'_, '_>> = doc
            .descendants()
            .filter(|n| n.has_tag_name("use"))
            .collect();
        let path = doc.descendants().find(|n| n.has_tag_name("path")).unwrap();
        assert_eq!(r.target(&uses[0]), Target::Element(path));
        assert_eq!(r.target(&uses[1]), Target::Element(path));
        assert!(matches!(r.target(&uses[2]), Target::NotFollowed(_)));
        assert_eq!(r.target(&uses[3]), Target::Missing);
        assert!(matches!(r.target(&uses[4]), Target::NotFollowed(_)));
        assert!(r.is_referenced(&path));
    }

    #[test]
    fn a_chain_returning_to_an_element_it_draws_loops() {
        let doc = Document::parse(
            r##"<svg><g id="a"><use id="ua" href="#b"/></g><g id="b"><use id="ub" href="#a"/></g></svg>"##,
        )
        .unwrap();
        let mut r = References::new(&doc);
        let by_id = |id: &str| {
            doc.descendants()
                .find(|n| n.attribute("id") == Some(id))
                .unwrap()
        };
        let (a, b, ua, ub) = (by_id("a"), by_id("b"), by_id("ua"), by_id("ub"));
        // Walking a: its use draws b (no loop yet), b's use draws a, which the chain holds.
        assert!(!r.loops(&ua, &b, None));
        let chain = r.extend(&b, None);
        assert!(!r.loops(&ub, &a, Some(chain)));
        let chain2 = r.extend(&a, Some(chain));
        assert!(r.loops(&ua, &b, Some(chain2)));
        // A use inside the element it references loops at once.
        assert!(r.loops(&ua, &a, None));
    }
}
