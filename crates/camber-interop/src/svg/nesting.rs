//! A scan of a document's element nesting before the XML reader sees it: the reader descends
//! one call per nested element, so a document nested a million deep would overflow the stack
//! there. The scan is a loop over the bytes, allocates nothing, and finds the first element
//! deeper than the budget.
//!
//! It skips comments, CDATA sections, processing instructions and quoted attribute values
//! (which may hold `>`), counts `<name …>` as one level down, `</name>` as one up and
//! `<name …/>` as a leaf. Entities could hide elements from it, so a DTD whose internal subset
//! could declare markup (a `<` that starts no declaration, or a character reference, which
//! entity values expand when declared) is refused.

/// The first element nested deeper than `max_depth` (the root at depth 0): its depth, tag and
/// byte offset.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct TooDeep {
    pub(crate) depth: usize,
    pub(crate) tag: String,
    pub(crate) offset: usize,
}

/// What the scan found wrong.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum Finding {
    /// An element deeper than the budget.
    TooDeep(TooDeep),
    /// A DTD that could declare elements.
    MarkupInDtd {
        /// Its byte offset.
        offset: usize,
    },
}

fn find(text: &[u8], from: usize, pattern: &[u8]) -> usize {
    text.get(from..)
        .and_then(|rest| rest.windows(pattern.len()).position(|w| w == pattern))
        .map_or(text.len(), |k| from + k + pattern.len())
}

/// The end (one past `>`) of the tag starting at `from`, quoted values skipped.
fn tag_end(text: &[u8], from: usize) -> usize {
    let mut i = from;
    let mut quote = None;
    while let Some(&c) = text.get(i) {
        match quote {
            Some(q) if c == q => quote = None,
            Some(_) => {}
            None if c == b'"' || c == b'\'' => quote = Some(c),
            None if c == b'>' => return i + 1,
            None => {}
        }
        i += 1;
    }
    text.len()
}

/// The end of a `<!…>` declaration (a DOCTYPE with its internal subset), and whether its
/// subset could declare markup.
fn declaration_end(text: &[u8], from: usize) -> (usize, bool) {
    let mut i = from + 2;
    let mut brackets = 0usize;
    let mut quote = None;
    let mut markup = false;
    while let Some(&c) = text.get(i) {
        match quote {
            Some(q) if c == q => quote = None,
            Some(_) => {
                if c == b'<' || (c == b'&' && text.get(i + 1) == Some(&b'#')) {
                    markup = true;
                }
            }
            None => match c {
                b'"' | b'\'' => quote = Some(c),
                b'[' => brackets += 1,
                b']' => brackets = brackets.saturating_sub(1),
                b'<' if brackets > 0 && !matches!(text.get(i + 1), Some(b'!' | b'?')) => {
                    markup = true;
                }
                b'>' if brackets == 0 => return (i + 1, markup),
                _ => {}
            },
        }
        i += 1;
    }
    (text.len(), markup)
}

/// Scans `text` (see the module documentation).
pub(crate) fn scan(text: &str, max_depth: usize) -> Option<Finding> {
    let b = text.as_bytes();
    let mut open = 0usize;
    let mut i = 0;
    while i < b.len() {
        if b[i] != b'<' {
            i += 1;
            continue;
        }
        let rest = &b[i..];
        if rest.starts_with(b"<!--") {
            i = find(b, i + 4, b"-->");
        } else if rest.starts_with(b"<![CDATA[") {
            i = find(b, i + 9, b"]]>");
        } else if rest.starts_with(b"<?") {
            i = find(b, i + 2, b"?>");
        } else if rest.starts_with(b"<!") {
            let (end, markup) = declaration_end(b, i);
            if markup {
                return Some(Finding::MarkupInDtd { offset: i });
            }
            i = end;
        } else if rest.starts_with(b"</") {
            open = open.saturating_sub(1);
            i = tag_end(b, i);
        } else {
            let end = tag_end(b, i);
            // The element is at depth `open` (the root at 0).
            if open > max_depth {
                let name: String = text[i + 1..end.min(text.len())]
                    .chars()
                    .take_while(|c| !c.is_whitespace() && *c != '>' && *c != '/')
                    .take(64)
                    .collect();
                return Some(Finding::TooDeep(TooDeep {
                    depth: open,
                    tag: name,
                    offset: i,
                }));
            }
            if end < 2 || b.get(end - 2) != Some(&b'/') {
                open += 1;
            }
            i = end;
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn depth_counts_elements_not_comments_quotes_or_leaves() {
        let doc = r#"<svg><!-- <g><g><g> --><g a="<g>" b='/>'><path/><![CDATA[<g><g>]]><g><p/></g></g></svg>"#;
        // svg (0) > g (1) > path (2), g (2) > p (3).
        assert_eq!(scan(doc, 3), None);
        assert_eq!(
            scan(doc, 2),
            Some(Finding::TooDeep(TooDeep {
                depth: 3,
                tag: "p".into(),
                offset: 69
            }))
        );
        assert!(
            matches!(scan(doc, 1), Some(Finding::TooDeep(TooDeep { depth: 2, ref tag, .. })) if tag == "path")
        );
    }

    #[test]
    fn a_dtd_that_could_declare_elements_is_found() {
        let plain = r#"<!DOCTYPE svg PUBLIC "-//W3C//DTD SVG 1.1//EN" "http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd"><svg/>"#;
        assert_eq!(scan(plain, 4), None);
        let text_entity = r#"<!DOCTYPE svg [<!ENTITY ns "http://x"><!-- c -->]><svg/>"#;
        assert_eq!(scan(text_entity, 4), None);
        for hostile in [
            r#"<!DOCTYPE svg [<!ENTITY e "<g><g></g></g>">]><svg>&e;</svg>"#,
            r#"<!DOCTYPE svg [<!ENTITY e "&#60;g/>">]><svg>&e;</svg>"#,
        ] {
            assert_eq!(
                scan(hostile, 4),
                Some(Finding::MarkupInDtd { offset: 0 }),
                "{hostile}"
            );
        }
    }
}
