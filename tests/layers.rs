//! The layering of camber-solve and camber-sketch, read from their sources.
//!
//! Each crate is a stack of layers (docs/architecture.md draws them); a source file may name
//! items of its own layer and of the layers below it, never of a layer above. This test reads
//! every `.rs` file of the two crates, finds each `crate::…` path in its code (comments and the
//! `#[cfg(test)]` module at the end of a file are left out: tests may drive the whole crate) and
//! fails on every path that runs upward, naming the file, the line and the layers.

use std::path::{Path, PathBuf};

/// One crate's layers, bottom first: each entry is the layer's name and the module paths (as
/// they follow `crate::`, a `/` for each `::`) that belong to it. A path belongs to the layer
/// of its longest listed prefix.
struct Stack {
    dir: &'static str,
    layers: &'static [(&'static str, &'static [&'static str])],
}

/// camber-solve: model → derive → linalg → analysis → solvers → policy, then the crate root
/// (lib.rs, which re-exports the public face: nothing inside may import through it).
const SOLVE: Stack = Stack {
    dir: "crates/camber-solve/src",
    layers: &[
        ("model", &["model"]),
        ("derive", &["derive"]),
        ("linalg", &["linalg"]),
        ("analysis", &["analysis"]),
        ("solvers", &["solvers"]),
        ("policy", &["policy"]),
        ("root", &["lib"]),
    ],
};

/// camber-sketch: the ground → residuals → constraints → component → sketch → sessions and the
/// file format, then the crate root.
const SKETCH: Stack = Stack {
    dir: "crates/camber-sketch/src",
    layers: &[
        ("ground", &["ground"]),
        ("residuals", &["residuals"]),
        ("constraints", &["constraints"]),
        ("component", &["component"]),
        ("sketch", &["sketch"]),
        ("session", &["session", "file"]),
        ("root", &["lib"]),
    ],
};

impl Stack {
    /// The layer (index) of a module path such as `linalg/sparse` or `lib` (the root).
    fn layer_of(&self, module: &str) -> Option<usize> {
        let mut best: Option<(usize, usize)> = None;
        for (k, (_, prefixes)) in self.layers.iter().enumerate() {
            for p in *prefixes {
                let hit = module == *p || module.starts_with(&format!("{p}/"));
                if hit && best.is_none_or(|(len, _)| p.len() > len) {
                    best = Some((p.len(), k));
                }
            }
        }
        best.map(|(_, k)| k)
    }

    /// The layer a `crate::a::b…` path names: its first segment when that is a module of the
    /// crate (a folder or a file under src/), the root otherwise (an item re-exported by lib.rs).
    fn layer_of_path(&self, root: &Path, first: &str) -> Option<usize> {
        let is_module = root.join(first).is_dir() || root.join(format!("{first}.rs")).is_file();
        if is_module {
            self.layer_of(first)
        } else {
            self.layer_of("lib")
        }
    }
}

/// Every `.rs` file under `dir`, recursively, sorted.
fn sources(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&d) else {
            continue;
        };
        for e in entries.flatten() {
            let p = e.path();
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|x| x == "rs") {
                out.push(p);
            }
        }
    }
    out.sort();
    out
}

/// The module path of a source file relative to src/ (`linalg/sparse`, `model`, `lib`).
fn module_of(root: &Path, file: &Path) -> String {
    let rel = file.strip_prefix(root).unwrap_or(file).with_extension("");
    let mut parts: Vec<String> = rel
        .components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect();
    if parts.last().is_some_and(|p| p == "mod") {
        parts.pop();
    }
    parts.join("/")
}

/// The code of a file line by line, without comments, string contents and the `#[cfg(test)]`
/// module at its end.
fn code_lines(text: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    let mut in_block_comment = false;
    let lines: Vec<&str> = text.lines().collect();
    for (n, line) in lines.iter().enumerate() {
        let test_module = lines
            .get(n + 1)
            .is_some_and(|next| next.starts_with("mod "));
        if line.starts_with("#[cfg(test)]") && test_module {
            break;
        }
        let mut code = String::new();
        let mut chars = line.chars().peekable();
        let mut in_string = false;
        while let Some(c) = chars.next() {
            if in_block_comment {
                if c == '*' && chars.peek() == Some(&'/') {
                    chars.next();
                    in_block_comment = false;
                }
                continue;
            }
            if in_string {
                if c == '\\' {
                    chars.next();
                } else if c == '"' {
                    in_string = false;
                }
                continue;
            }
            match c {
                '/' if chars.peek() == Some(&'/') => break,
                '/' if chars.peek() == Some(&'*') => {
                    chars.next();
                    in_block_comment = true;
                }
                '"' => in_string = true,
                _ => code.push(c),
            }
        }
        out.push((n + 1, code));
    }
    out
}

/// The first segment of every `crate::…` path in a line of code, a group
/// `crate::{a::x, b}` giving each of its members' first segments.
fn crate_paths(code: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = code;
    while let Some(at) = rest.find("crate::") {
        let before = rest[..at].chars().next_back();
        rest = &rest[at + "crate::".len()..];
        if before.is_some_and(|c| c.is_alphanumeric() || c == '_') {
            continue; // `my_crate::` or similar
        }
        if let Some(group) = rest.strip_prefix('{') {
            let mut depth = 1;
            let mut member = String::new();
            let mut members = Vec::new();
            for c in group.chars() {
                match c {
                    '{' => depth += 1,
                    '}' => {
                        depth -= 1;
                        if depth == 0 {
                            break;
                        }
                    }
                    ',' if depth == 1 => members.push(std::mem::take(&mut member)),
                    _ if depth == 1 => member.push(c),
                    _ => {}
                }
            }
            members.push(member);
            for m in members {
                let first: String = m
                    .trim()
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                if !first.is_empty() && first != "self" {
                    out.push(first);
                }
            }
        } else {
            let first: String = rest
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            if !first.is_empty() {
                out.push(first);
            }
        }
    }
    out
}

/// Every import of a crate that runs upward, as readable lines.
fn upward_imports(stack: &Stack) -> Vec<String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join(stack.dir);
    let files = sources(&root);
    assert!(
        files.len() > 10,
        "no sources found under {}",
        root.display()
    );
    let mut found = Vec::new();
    for file in files {
        let module = module_of(&root, &file);
        let Some(own) = stack.layer_of(&module) else {
            found.push(format!("{}: in no layer", file.display()));
            continue;
        };
        let text = std::fs::read_to_string(&file).unwrap_or_default();
        for (line, code) in code_lines(&text) {
            for first in crate_paths(&code) {
                let Some(target) = stack.layer_of_path(&root, &first) else {
                    found.push(format!(
                        "{}:{line}: crate::{first} is in no layer",
                        file.display()
                    ));
                    continue;
                };
                if target > own {
                    found.push(format!(
                        "{}:{line}: {} imports crate::{first} from {} above it",
                        file.display(),
                        stack.layers[own].0,
                        stack.layers[target].0
                    ));
                }
            }
        }
    }
    found
}

#[test]
fn camber_solve_imports_only_downward() {
    let upward = upward_imports(&SOLVE);
    assert!(upward.is_empty(), "{}", upward.join("\n"));
}

#[test]
fn camber_sketch_imports_only_downward() {
    let upward = upward_imports(&SKETCH);
    assert!(upward.is_empty(), "{}", upward.join("\n"));
}

/// Files of camber-sketch's constraints/ that are not constraint kinds: what kinds compile
/// with and share.
const KIND_INFRASTRUCTURE: &[&str] = &["mod", "compiler", "glyph", "check", "piece", "shared"];

/// Every place a constraint kind's file names a sibling kind's module: helpers kinds share
/// belong in constraints/shared/, never in one kind's file for the others to borrow.
fn sibling_borrows() -> Vec<String> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("crates/camber-sketch/src/constraints");
    let kinds: Vec<String> = sources(&dir)
        .iter()
        .filter(|p| p.parent() == Some(dir.as_path()))
        .filter_map(|p| p.file_stem().map(|s| s.to_string_lossy().into_owned()))
        .filter(|s| !KIND_INFRASTRUCTURE.contains(&s.as_str()))
        .collect();
    assert!(kinds.len() > 20, "found only {} kinds", kinds.len());
    let mut found = Vec::new();
    for kind in &kinds {
        let file = dir.join(format!("{kind}.rs"));
        let text = std::fs::read_to_string(&file).unwrap_or_default();
        for (line, code) in code_lines(&text) {
            for other in kinds.iter().filter(|k| *k != kind) {
                let named = [
                    format!("super::{other}::"),
                    format!("constraints::{other}::"),
                ];
                if named.iter().any(|n| code.contains(n.as_str())) {
                    found.push(format!("{}:{line}: borrows from {other}", file.display()));
                }
            }
        }
    }
    found
}

#[test]
fn constraint_kinds_borrow_nothing_from_each_other() {
    let borrows = sibling_borrows();
    assert!(borrows.is_empty(), "{}", borrows.join("\n"));
}

#[test]
fn the_checker_finds_an_upward_import() {
    // A path into a layer above is reported, one into a layer below is not; comments, strings
    // and grouped imports are read as code is.
    assert_eq!(
        crate_paths("use crate::{linalg::sparse::SparseMatrix, model};"),
        ["linalg", "model"]
    );
    let lines = code_lines(
        "let a = crate::x; // crate::y\nlet s = \"crate::z\";\n#[cfg(test)]\nmod tests {\ncrate::w",
    );
    let paths: Vec<String> = lines.iter().flat_map(|(_, c)| crate_paths(c)).collect();
    assert_eq!(paths, ["x"]);
    assert_eq!(SOLVE.layer_of("model/problem"), Some(0));
    assert_eq!(SOLVE.layer_of("policy"), Some(5));
    assert_eq!(SKETCH.layer_of("file/raw"), Some(5));
}
