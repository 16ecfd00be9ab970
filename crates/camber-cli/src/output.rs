//! Writing a command's output files all or nothing.
//!
//! A command first computes every file it writes, then hands them to [`write_all`]: the paths
//! are checked (no output may be one of the command's inputs, nor another output), each text
//! goes to a temporary file in its target's directory, and only when every temporary file is
//! written are they renamed over their targets. A failure anywhere leaves every target as it
//! was. A target that is a symbolic link keeps the link (its target file is replaced), and an
//! existing file keeps its permissions.
//!
//! ```
//! use camber_cli::output::write_all;
//! let dir = tempfile::tempdir()?;
//! let (a, b) = (dir.path().join("a.json"), dir.path().join("b.json"));
//! write_all(&[], &[(a.clone(), "1".into()), (b.clone(), "2".into())])?;
//! assert_eq!(std::fs::read_to_string(&b)?, "2");
//! // The same path twice is refused before anything is written.
//! let c = dir.path().join("c.json");
//! assert!(write_all(&[], &[(c.clone(), "x".into()), (c.clone(), "y".into())]).is_err());
//! assert!(!c.exists());
//! # Ok::<(), anyhow::Error>(())
//! ```

use std::path::{Path, PathBuf};

use anyhow::{anyhow, bail, Result};

/// Where writing `path` really lands: a symbolic link is followed to its target (so the link
/// stays a link), and the result is made absolute through its existing parent directory, so
/// that two spellings of one file compare equal.
fn resolve(path: &Path) -> Result<PathBuf> {
    if let Ok(real) = std::fs::canonicalize(path) {
        return Ok(real);
    }
    // A new file (or a dangling link): follow a link by hand, then canonicalize the parent.
    let target = match std::fs::read_link(path) {
        Ok(t) if t.is_absolute() => t,
        Ok(t) => path.parent().unwrap_or(Path::new(".")).join(t),
        Err(_) => path.to_path_buf(),
    };
    let name = target
        .file_name()
        .ok_or_else(|| anyhow!("{}: not a file name", path.display()))?;
    let parent = match target.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let parent = std::fs::canonicalize(&parent).map_err(|e| {
        anyhow!(
            "{}: cannot write: folder {}: {}",
            path.display(),
            parent.display(),
            crate::curve_file::io_reason(&e)
        )
    })?;
    Ok(parent.join(name))
}

/// Writes every `(path, text)` of `outputs`, all or nothing (see the module docs).
///
/// # Errors
/// An output that is one of `inputs` or appears twice (nothing is written then); a file that
/// cannot be written (every temporary file is removed and no target changes).
pub fn write_all(inputs: &[&Path], outputs: &[(PathBuf, String)]) -> Result<()> {
    write_all_of(inputs, outputs)
}

/// [`write_all`] for outputs of bytes (a binary DXF file, say).
///
/// # Errors
/// As [`write_all`].
pub fn write_all_bytes(inputs: &[&Path], outputs: &[(PathBuf, Vec<u8>)]) -> Result<()> {
    write_all_of(inputs, outputs)
}

fn write_all_of<C: AsRef<[u8]>>(inputs: &[&Path], outputs: &[(PathBuf, C)]) -> Result<()> {
    let input_files: Vec<PathBuf> = inputs
        .iter()
        .filter_map(|p| std::fs::canonicalize(p).ok())
        .collect();
    let mut targets: Vec<PathBuf> = Vec::with_capacity(outputs.len());
    for (path, _) in outputs {
        let real = resolve(path)?;
        if let Some(i) = input_files.iter().position(|f| *f == real) {
            bail!(
                "{}: refusing to overwrite the input {} with an output",
                path.display(),
                inputs[i].display()
            );
        }
        if let Some(j) = targets.iter().position(|t| *t == real) {
            bail!(
                "{}: the same file is given for two outputs ({} and {})",
                path.display(),
                outputs[j].0.display(),
                path.display()
            );
        }
        targets.push(real);
    }
    let mut written: Vec<PathBuf> = Vec::with_capacity(outputs.len());
    let clean = |written: &[PathBuf]| {
        for t in written {
            let _ = std::fs::remove_file(t);
        }
    };
    for ((path, text), target) in outputs.iter().zip(&targets) {
        match write_temporary(target, text.as_ref()) {
            Ok(tmp) => written.push(tmp),
            Err(e) => {
                clean(&written);
                return Err(anyhow!("{}: cannot write: {e}", path.display()));
            }
        }
    }
    for (i, (tmp, target)) in written.iter().zip(&targets).enumerate() {
        if let Err(e) = std::fs::rename(tmp, target) {
            clean(&written[i..]);
            return Err(anyhow!(
                "{}: cannot write: {}",
                outputs[i].0.display(),
                crate::curve_file::io_reason(&e)
            ));
        }
    }
    Ok(())
}

/// Writes `text` (bytes) to a new temporary file beside `target` (same directory, so the rename is
/// atomic), with `target`'s permissions when it exists; returns the temporary path.
fn write_temporary(target: &Path, text: &[u8]) -> std::result::Result<PathBuf, String> {
    use std::io::Write as _;
    let dir = target.parent().unwrap_or(Path::new("."));
    let name = target
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let reason = |e: std::io::Error| crate::curve_file::io_reason(&e);
    let mut n = 0u32;
    let (tmp, mut file) = loop {
        let tmp = dir.join(format!(".{name}.{}.{n}.camber-tmp", std::process::id()));
        match std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&tmp)
        {
            Ok(f) => break (tmp, f),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists && n < 100 => n += 1,
            Err(e) => return Err(reason(e)),
        }
    };
    let result = file
        .write_all(text)
        .and_then(|()| file.sync_all())
        .and_then(|()| match std::fs::metadata(target) {
            Ok(meta) => std::fs::set_permissions(&tmp, meta.permissions()),
            Err(_) => Ok(()),
        });
    if let Err(e) = result {
        let _ = std::fs::remove_file(&tmp);
        return Err(reason(e));
    }
    Ok(tmp)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_unwritable_output_leaves_every_other_one_unwritten() {
        let dir = tempfile::tempdir().unwrap();
        let ok = dir.path().join("ok.json");
        let bad = dir.path().join("no/such/folder/x.svg");
        assert!(write_all(&[], &[(ok.clone(), "a".into()), (bad, "b".into())]).is_err());
        assert!(!ok.exists());
        assert_eq!(
            std::fs::read_dir(dir.path()).unwrap().count(),
            0,
            "no temporary left"
        );
    }

    #[test]
    fn an_input_is_never_an_output() {
        let dir = tempfile::tempdir().unwrap();
        let input = dir.path().join("in.json");
        std::fs::write(&input, "keep").unwrap();
        let spelled = dir.path().join(".").join("in.json");
        let e = write_all(&[&input], &[(spelled, "x".into())]).unwrap_err();
        assert!(
            e.to_string().contains("refusing to overwrite the input"),
            "{e}"
        );
        assert_eq!(std::fs::read_to_string(&input).unwrap(), "keep");
    }

    #[cfg(unix)]
    #[test]
    fn a_link_stays_a_link_and_the_mode_is_kept() {
        use std::os::unix::fs::PermissionsExt as _;
        let dir = tempfile::tempdir().unwrap();
        let real = dir.path().join("real.json");
        std::fs::write(&real, "old").unwrap();
        std::fs::set_permissions(&real, std::fs::Permissions::from_mode(0o600)).unwrap();
        let link = dir.path().join("link.json");
        std::os::unix::fs::symlink(&real, &link).unwrap();
        write_all(&[], &[(link.clone(), "new".into())]).unwrap();
        assert!(std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink());
        assert_eq!(std::fs::read_to_string(&real).unwrap(), "new");
        let mode = std::fs::metadata(&real).unwrap().permissions().mode() & 0o777;
        assert_eq!(mode, 0o600);
    }
}
