//! The two presentation properties that decide whether an element is drawn: `display` (not
//! inherited; `none` removes the element and everything in it) and `visibility` (inherited;
//! `hidden` or `collapse` hides a shape, a descendant may say `visible` again). Each is read
//! from the element's inline `style` (declarations `name: value` separated by `;`, which win
//! over the attribute, as CSS ranks them) or its presentation attribute. Style sheets
//! (`<style>` and class selectors) are not read.

use roxmltree::Node;

/// The value of the property `name` on `node`: from its inline `style` if declared there (the
/// last declaration wins), else from its attribute; trimmed, `!important` dropped.
pub(crate) fn property<'a>(node: &Node<'a, '_>, name: &str) -> Option<&'a str> {
    let from_style = node.attribute("style").and_then(|style| {
        style
            .rsplit(';')
            .filter_map(|d| d.split_once(':'))
            .find(|(n, _)| n.trim() == name)
            .map(|(_, v)| v)
    });
    from_style
        .or_else(|| node.attribute(name))
        .map(|v| v.trim().trim_end_matches("!important").trim())
}

/// Whether `display: none` removes `node` from the drawing.
pub(crate) fn display_none(node: &Node<'_, '_>) -> bool {
    property(node, "display") == Some("none")
}

/// Whether shapes of `node` are hidden, given whether its parent's are (`inherit`, an
/// unknown value and no value keep the parent's).
pub(crate) fn hidden(node: &Node<'_, '_>, parent_hidden: bool) -> bool {
    match property(node, "visibility") {
        Some("hidden" | "collapse") => true,
        Some("visible") => false,
        _ => parent_hidden,
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

    use super::*;
    use roxmltree::Document;

    fn first<'a, 'i>(doc: &'a Document<'i>) -> Node<'a, 'i> {
        doc.root_element().first_element_child().unwrap()
    }

    #[test]
    fn inline_style_wins_over_the_attribute() {
        let doc =
            Document::parse(r#"<svg><g display="inline" style="fill:red; display : none"/></svg>"#)
                .unwrap();
        assert!(display_none(&first(&doc)));
        let doc =
            Document::parse(r#"<svg><g display="none" style="display:inline"/></svg>"#).unwrap();
        assert!(!display_none(&first(&doc)));
        let doc = Document::parse(r#"<svg><g display="none"/></svg>"#).unwrap();
        assert!(display_none(&first(&doc)));
        let doc = Document::parse(r#"<svg><g style="display:none !important"/></svg>"#).unwrap();
        assert!(display_none(&first(&doc)));
    }

    #[test]
    fn visibility_inherits_unless_restated() {
        let doc = Document::parse(r#"<svg><g visibility="hidden"/></svg>"#).unwrap();
        assert!(hidden(&first(&doc), false));
        let doc = Document::parse(r#"<svg><g style="visibility:visible"/></svg>"#).unwrap();
        assert!(!hidden(&first(&doc), true));
        let doc = Document::parse(r#"<svg><g visibility="inherit"/></svg>"#).unwrap();
        assert!(hidden(&first(&doc), true));
        assert!(!hidden(&first(&doc), false));
    }
}
