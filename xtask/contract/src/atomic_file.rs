//! Writing a file so that a run killed or failing half-way leaves the old file or none, never a
//! truncated one: the bytes go to a temporary file in the destination's directory (same file
//! system), which is flushed to disk and then renamed over the destination. Every file aokit
//! writes (images, reports, exports, the xtask's assets, scene caches) goes through here; it
//! lives in `aokit-vulkan` because both `aokit` and the xtask depend on this crate.
//!
//! Temporary files are named `.<file name>.<pid>.<counter>.aokit-tmp` and created with
//! `O_EXCL`, so concurrent runs (and threads) never share one; they are removed when the write
//! fails (or the closure panics). A run killed by a signal cannot remove its temporary file, but
//! the destination is intact.

use std::fs::{self, File, OpenOptions};
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// The suffix of every temporary file (`.<name>.<pid>.<counter>` before it).
pub const TEMP_SUFFIX: &str = ".aokit-tmp";

/// Write `path` atomically with `write`, which receives a buffered writer (`Write + Seek`, as
/// image encoders need) on the temporary file. The file's contents reach the disk (`fsync`)
/// before the rename; an existing destination's permissions are kept, and a symbolic link is
/// followed (its target is replaced, not the link). Errors are one line naming `path`.
pub fn write_atomic<F>(path: &Path, write: F) -> io::Result<()>
where
    F: FnOnce(&mut BufWriter<File>) -> io::Result<()>,
{
    write_inner(path, write).map_err(|e| io::Error::new(e.kind(), format!("{}: {e}", path.display())))
}

/// [`write_atomic`] of a byte slice.
pub fn write_atomic_bytes(path: &Path, bytes: &[u8]) -> io::Result<()> {
    write_atomic(path, |w| w.write_all(bytes))
}

/// Whether `name` (a file name) is one of [`write_atomic`]'s temporary files.
pub fn is_temp_name(name: &str) -> bool {
    name.starts_with('.') && name.ends_with(TEMP_SUFFIX)
}

fn write_inner<F>(path: &Path, write: F) -> io::Result<()>
where
    F: FnOnce(&mut BufWriter<File>) -> io::Result<()>,
{
    let dest = follow_link(path);
    let name = dest
        .file_name()
        .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidInput, "not a file path"))?
        .to_string_lossy()
        .into_owned();
    let dir = match dest.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    let (file, temp) = create_temp(dir, &name)?;
    let mut writer = BufWriter::new(file);
    write(&mut writer)?;
    let file = writer.into_inner().map_err(io::IntoInnerError::into_error)?;
    if let Ok(meta) = fs::metadata(&dest)
        && meta.is_file()
    {
        file.set_permissions(meta.permissions())?;
    }
    file.sync_all()?;
    drop(file);
    fs::rename(temp.path(), &dest)?;
    temp.keep();
    // The rename itself reaches the disk with the directory (best effort: not every file
    // system lets a directory be opened and synced).
    if let Ok(d) = File::open(dir) {
        let _ = d.sync_all();
    }
    Ok(())
}

/// The file a write to `path` replaces: the target of a symbolic link, `path` otherwise.
fn follow_link(path: &Path) -> PathBuf {
    match fs::symlink_metadata(path) {
        Ok(m) if m.file_type().is_symlink() => fs::canonicalize(path).unwrap_or_else(|_| {
            // A dangling link: create its target, as a plain write would.
            match fs::read_link(path) {
                Ok(t) if t.is_relative() => path.parent().unwrap_or(Path::new("")).join(t),
                Ok(t) => t,
                Err(_) => path.to_path_buf(),
            }
        }),
        _ => path.to_path_buf(),
    }
}

/// A temporary file that is removed when dropped, unless kept.
struct Temp(Option<PathBuf>);

impl Temp {
    fn path(&self) -> &Path {
        self.0.as_deref().expect("not kept yet")
    }

    fn keep(mut self) {
        self.0 = None;
    }
}

impl Drop for Temp {
    fn drop(&mut self) {
        if let Some(p) = self.0.take() {
            let _ = fs::remove_file(p);
        }
    }
}

/// A new, empty temporary file next to `name` in `dir`, unique to this process and call.
fn create_temp(dir: &Path, name: &str) -> io::Result<(File, Temp)> {
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    // Room for the suffix within the usual 255-byte limit of a file name.
    let mut end = name.len().min(180);
    while !name.is_char_boundary(end) {
        end -= 1;
    }
    let stem = &name[..end];
    let pid = std::process::id();
    loop {
        let n = COUNTER.fetch_add(1, Ordering::Relaxed);
        let temp = dir.join(format!(".{stem}.{pid}.{n}{TEMP_SUFFIX}"));
        match OpenOptions::new().write(true).create_new(true).open(&temp) {
            Ok(file) => return Ok((file, Temp(Some(temp)))),
            // Left by a killed run whose pid this process now has.
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(e),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("aokit-atomic-{name}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        dir
    }

    fn entries(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> =
            fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        v.sort();
        v
    }

    #[test]
    fn replaces_and_leaves_no_temp() {
        let dir = scratch("replace");
        let path = dir.join("out.json");
        fs::write(&path, "old").unwrap();
        write_atomic_bytes(&path, b"new contents").unwrap();
        assert_eq!(fs::read(&path).unwrap(), b"new contents");
        write_atomic_bytes(&dir.join("second.bin"), &[1, 2, 3]).unwrap();
        assert_eq!(entries(&dir), ["out.json", "second.bin"]);
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn failure_keeps_old_file_and_removes_temp() {
        let dir = scratch("fail");
        let path = dir.join("out.png");
        fs::write(&path, "old").unwrap();
        let e = write_atomic(&path, |w| {
            w.write_all(&[0; 100_000])?;
            Err(io::Error::other("encoder failed"))
        })
        .unwrap_err();
        assert_eq!(e.to_string(), format!("{}: encoder failed", path.display()));
        assert_eq!(fs::read(&path).unwrap(), b"old");
        assert_eq!(entries(&dir), ["out.png"]);
        // A panic in the closure too.
        let caught = std::panic::catch_unwind(|| write_atomic(&path, |_| panic!("boom")));
        assert!(caught.is_err());
        assert_eq!(entries(&dir), ["out.png"]);
        // The rename fails: the destination is a directory.
        fs::create_dir(dir.join("sub")).unwrap();
        fs::write(dir.join("sub/keep"), "kept").unwrap();
        let e = write_atomic_bytes(&dir.join("sub"), b"x").unwrap_err();
        assert!(e.to_string().starts_with(&dir.join("sub").display().to_string()), "{e}");
        assert!(!e.to_string().contains('\n'));
        assert_eq!(fs::read(dir.join("sub/keep")).unwrap(), b"kept");
        assert_eq!(entries(&dir), ["out.png", "sub"]);
        // The directory does not exist.
        let e = write_atomic_bytes(&dir.join("missing/x.json"), b"x").unwrap_err();
        assert!(e.to_string().starts_with(&dir.join("missing/x.json").display().to_string()), "{e}");
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn concurrent_writers_never_share_a_temp() {
        let dir = scratch("concurrent");
        let path = dir.join("shared.bin");
        std::thread::scope(|s| {
            for t in 0..8u8 {
                let path = &path;
                s.spawn(move || {
                    for _ in 0..20 {
                        write_atomic(path, |w| {
                            for _ in 0..64 {
                                w.write_all(&[t; 1024])?;
                            }
                            Ok(())
                        })
                        .unwrap();
                    }
                });
            }
        });
        let bytes = fs::read(&path).unwrap();
        assert_eq!(bytes.len(), 64 * 1024);
        assert!(bytes.iter().all(|&b| b == bytes[0]), "mixed writers");
        assert_eq!(entries(&dir), ["shared.bin"]);
        fs::remove_dir_all(&dir).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn keeps_permissions_and_follows_links() {
        use std::os::unix::fs::PermissionsExt;
        let dir = scratch("perms");
        let path = dir.join("tool.sh");
        fs::write(&path, "old").unwrap();
        fs::set_permissions(&path, fs::Permissions::from_mode(0o750)).unwrap();
        write_atomic_bytes(&path, b"new").unwrap();
        assert_eq!(fs::metadata(&path).unwrap().permissions().mode() & 0o777, 0o750);
        let link = dir.join("link.sh");
        std::os::unix::fs::symlink("tool.sh", &link).unwrap();
        write_atomic_bytes(&link, b"through the link").unwrap();
        assert!(fs::symlink_metadata(&link).unwrap().file_type().is_symlink());
        assert_eq!(fs::read(&path).unwrap(), b"through the link");
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn temp_names() {
        assert!(is_temp_name(".out.png.123.0.aokit-tmp"));
        assert!(!is_temp_name("out.png"));
    }
}
