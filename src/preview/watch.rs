//! Live editing: the scene and the files it included are watched (notify crate), and a change
//! to one of them calls back, so that the window parses the scene again. Directories are
//! watched rather than the files, since editors save by writing a new file and renaming it
//! over the old one.

use std::collections::HashSet;
use std::path::{Path, PathBuf};

use notify::{EventKind, RecursiveMode, Watcher};

/// Watches files while it lives.
pub struct Watch {
    _watcher: notify::RecommendedWatcher,
}

impl Watch {
    /// Calls `changed` whenever one of `files` is written, created or replaced. None when the
    /// system refuses to watch (the window then just does not reload).
    pub fn new(files: &[PathBuf], changed: impl Fn() + Send + 'static) -> Option<Watch> {
        let names: HashSet<PathBuf> = files.iter().filter_map(|f| canonical(f)).collect();
        let dirs: HashSet<PathBuf> = names
            .iter()
            .filter_map(|f| f.parent().map(Path::to_path_buf))
            .collect();
        let mut watcher = notify::recommended_watcher(move |ev: notify::Result<notify::Event>| {
            let Ok(ev) = ev else { return };
            let writes = matches!(
                ev.kind,
                EventKind::Modify(_) | EventKind::Create(_) | EventKind::Remove(_)
            );
            let ours = ev
                .paths
                .iter()
                .any(|p| names.contains(p) || canonical(p).is_some_and(|c| names.contains(&c)));
            if writes && ours {
                changed();
            }
        })
        .ok()?;
        for d in &dirs {
            // A directory that cannot be watched only loses live reloading for its files.
            let _ = watcher.watch(d, RecursiveMode::NonRecursive);
        }
        Some(Watch { _watcher: watcher })
    }
}

fn canonical(p: &Path) -> Option<PathBuf> {
    std::fs::canonicalize(p).ok()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicBool, Ordering};
    use std::sync::Arc;
    use std::time::{Duration, Instant};

    /// Replacing a watched file by rename, as editors save, is seen.
    #[test]
    fn a_saved_file_is_seen() {
        let dir = std::env::temp_dir().join(format!("lancer-watch-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join("scene.pov");
        std::fs::write(&file, "sphere { 0, 1 }").unwrap();
        let seen = Arc::new(AtomicBool::new(false));
        let s = seen.clone();
        let _w = Watch::new(std::slice::from_ref(&file), move || {
            s.store(true, Ordering::SeqCst)
        })
        .unwrap();
        let tmp = dir.join("scene.pov.tmp");
        std::fs::write(&tmp, "sphere { 0, 2 }").unwrap();
        std::fs::rename(&tmp, &file).unwrap();
        let start = Instant::now();
        // Up to 5 s for the notification: generous for a loaded machine.
        while !seen.load(Ordering::SeqCst) && start.elapsed() < Duration::from_secs(5) {
            std::thread::sleep(Duration::from_millis(20));
        }
        let _ = std::fs::remove_dir_all(&dir);
        assert!(seen.load(Ordering::SeqCst));
    }
}
