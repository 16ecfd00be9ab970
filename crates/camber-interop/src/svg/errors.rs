//! Why an SVG import failed: every error names the offending item (the path data, or an
//! element by its tag, id and line), the command index and letter where a command is at fault,
//! and the value.

/// The item of the input an error or a skip is about.
///
/// ```
/// use camber_interop::svg::Item;
/// let wing = Item::Element { tag: "path".into(), id: Some("wing".into()), line: 12 };
/// assert_eq!(wing.to_string(), "<path id=\"wing\"> (line 12)");
/// assert_eq!(Item::PathData.to_string(), "the path data");
/// ```
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum Item {
    /// The path data given to [`import_path`](super::import_path).
    PathData,
    /// An element of a document.
    Element {
        /// Its tag (`path`, `rect`, …).
        tag: String,
        /// Its `id` attribute, if it has one.
        id: Option<String>,
        /// The line of the file it starts on, from 1.
        line: u32,
    },
}

impl std::fmt::Display for Item {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Item::PathData => write!(f, "the path data"),
            Item::Element { tag, id, line } => match id {
                Some(id) => write!(f, "<{tag} id=\"{id}\"> (line {line})"),
                None => write!(f, "<{tag}> (line {line})"),
            },
        }
    }
}

/// An SVG import that could not be done. Nothing is half imported: an error means no sketch.
///
/// ```
/// use camber_interop::svg::{import_path, Error, Item, SvgOptions};
/// let e = import_path("M 0 0 L 1", &SvgOptions::default()).unwrap_err();
/// assert!(matches!(e, Error::MalformedPath { item: Item::PathData, command: 1, .. }));
/// // svgtypes refuses a number beyond f64's range as written …
/// let e = import_path("M 0 0 L 1e999 0", &SvgOptions::default()).unwrap_err();
/// assert!(matches!(e, Error::MalformedPath { command: 1, .. }));
/// // … and the importer a point that overflows on the way.
/// let e = import_path("M 1e308 0 l 1e308 0", &SvgOptions::default()).unwrap_err();
/// assert!(matches!(e, Error::NonFinite { command: 1, letter: 'l', what: "x", .. }));
/// ```
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// The input is larger than [`SvgOptions::max_input_bytes`](super::SvgOptions).
    ///
    /// ```
    /// use camber_interop::svg::{import_path, Error, SvgOptions};
    /// let small = SvgOptions::default().with_max_input_bytes(8);
    /// assert_eq!(import_path("M 0 0 L 10 10", &small).unwrap_err(), Error::InputTooLarge { bytes: 13, max: 8 });
    /// ```
    #[error("the input is {bytes} bytes, above the budget of {max}")]
    InputTooLarge {
        /// Its size.
        bytes: usize,
        /// The budget.
        max: usize,
    },
    /// The document is not well-formed XML (or has more nodes than the budget).
    ///
    /// ```
    /// use camber_interop::svg::{import_document, Error, SvgOptions};
    /// assert!(matches!(import_document("<svg><path></svg>", &SvgOptions::default()), Err(Error::Xml { .. })));
    /// ```
    #[error("the document is not readable XML: {message}")]
    Xml {
        /// The XML reader's message, with the position.
        message: String,
    },
    /// The document's root element is not `<svg>`.
    ///
    /// ```
    /// use camber_interop::svg::{import_document, Error, SvgOptions};
    /// assert_eq!(import_document("<html/>", &SvgOptions::default()).unwrap_err(), Error::NotSvg { root: "html".into() });
    /// ```
    #[error("the document's root element is <{root}>, not <svg>")]
    NotSvg {
        /// The root's tag.
        root: String,
    },
    /// Elements are nested deeper than [`SvgOptions::max_depth`](super::SvgOptions).
    ///
    /// ```
    /// use camber_interop::svg::{import_document, Error, SvgOptions};
    /// let deep = format!("<svg>{}{}</svg>", "<g>".repeat(300), "</g>".repeat(300));
    /// assert!(matches!(import_document(&deep, &SvgOptions::default()), Err(Error::TooDeep { max: 256, .. })));
    /// ```
    #[error("{item} is nested {depth} elements deep, above the budget of {max}")]
    TooDeep {
        /// The element past the budget.
        item: Item,
        /// Its depth (the root is 0).
        depth: usize,
        /// The budget.
        max: usize,
    },
    /// A path command that cannot be read (svgtypes' message, with the character position).
    ///
    /// ```
    /// use camber_interop::svg::{import_path, Error, SvgOptions};
    /// assert!(matches!(import_path("M 0 0 X 1 1", &SvgOptions::default()), Err(Error::MalformedPath { command: 1, .. })));
    /// ```
    #[error("{item}, command {command}: malformed path data: {message}")]
    MalformedPath {
        /// The path.
        item: Item,
        /// The command's index (from 0, implicit repeats counted).
        command: usize,
        /// What is wrong.
        message: String,
    },
    /// A number that is not finite: a point that overflows on the way (a relative command
    /// adding to a huge current point). Numbers written beyond f64's range are
    /// [`Error::MalformedPath`], as svgtypes reads them.
    ///
    /// ```
    /// use camber_interop::svg::{import_path, Error, SvgOptions};
    /// let e = import_path("M 0 0 l 1e308 0 l 1e308 0", &SvgOptions::default()).unwrap_err();
    /// assert!(matches!(e, Error::NonFinite { command: 2, letter: 'l', what: "x", .. }));
    /// ```
    #[error("{item}, command {command} ({letter}): {what} is {value}, not a finite number")]
    NonFinite {
        /// The path.
        item: Item,
        /// The command's index.
        command: usize,
        /// Its letter.
        letter: char,
        /// Which number.
        what: &'static str,
        /// Its value.
        value: f64,
    },
    /// More drawing segments than [`SvgOptions::max_segments`](super::SvgOptions), counted
    /// over the whole input before any is built.
    ///
    /// ```
    /// use camber_interop::svg::{import_path, Error, Item, SvgOptions};
    /// let few = SvgOptions::default().with_max_segments(2);
    /// let e = import_path("M 0 0 L 1 0 L 1 1 L 0 1", &few).unwrap_err();
    /// assert_eq!(e, Error::TooManySegments { item: Item::PathData, command: 3, max: 2 });
    /// ```
    #[error("{item}, command {command}: more than {max} segments, the budget")]
    TooManySegments {
        /// The path.
        item: Item,
        /// The command past the budget.
        command: usize,
        /// The budget.
        max: usize,
    },
    /// An attribute whose value cannot be read (a `transform`, a shape's size or points).
    ///
    /// ```
    /// use camber_interop::svg::{import_document, Error, SvgOptions};
    /// let doc = r#"<svg><path transform="rotate(oops)" d="M 0 0 L 1 1"/></svg>"#;
    /// assert!(matches!(import_document(doc, &SvgOptions::default()), Err(Error::MalformedAttribute { attribute: "transform", .. })));
    /// ```
    #[error("{item}: attribute {attribute}=\"{value}\" cannot be read: {message}")]
    MalformedAttribute {
        /// The element.
        item: Item,
        /// The attribute's name.
        attribute: &'static str,
        /// Its value as written (up to 80 characters).
        value: String,
        /// What is wrong.
        message: String,
    },
    /// A `use` whose reference leads back to itself: it references the element it is in, or
    /// a chain of `use`s returns to an element it is already drawing.
    ///
    /// ```
    /// use camber_interop::svg::{import_document, Error, SvgOptions};
    /// let doc = r##"<svg><g id="a"><use href="#a"/></g></svg>"##;
    /// let e = import_document(doc, &SvgOptions::default()).unwrap_err();
    /// assert!(matches!(e, Error::ReferenceLoop { ref href, .. } if href == "#a"));
    /// ```
    #[error("{item}: href=\"{href}\" leads back to an element it is drawing (a reference loop)")]
    ReferenceLoop {
        /// The `use` that closes the loop.
        item: Item,
        /// Its reference, as written (up to 80 characters).
        href: String,
    },
    /// More elements drawn through `use` references than
    /// [`SvgOptions::max_use_elements`](super::SvgOptions): references that multiply.
    ///
    /// ```
    /// use camber_interop::svg::{import_document, Error, SvgOptions};
    /// // Each level draws the one below twice: 2 + 4 + 8 + … elements.
    /// let mut doc = String::from(r#"<svg><defs><path id="l0" d="M 0 0 L 1 0"/>"#);
    /// for k in 1..40 {
    ///     doc += &format!(r##"<g id="l{k}"><use href="#l{j}"/><use href="#l{j}"/></g>"##, j = k - 1);
    /// }
    /// doc += r##"</defs><use href="#l39"/></svg>"##;
    /// let e = import_document(&doc, &SvgOptions::default()).unwrap_err();
    /// assert!(matches!(e, Error::TooManyUseElements { max: 100_000, .. }));
    /// ```
    #[error("{item}: more than {max} elements drawn through use references, the budget")]
    TooManyUseElements {
        /// The element past the budget.
        item: Item,
        /// The budget.
        max: usize,
    },
    /// The sketch refused an entity or a constraint the importer made (a bug of the importer;
    /// reported rather than hidden).
    #[error("{item}, command {command}: the sketch refused it: {cause}")]
    Sketch {
        /// The path.
        item: Item,
        /// The command whose segment or join it was.
        command: usize,
        /// The sketch's error.
        #[source]
        cause: Box<camber_sketch::Error>,
    },
}
