//! The cache of POV-Ray's renders, keyed by the scene's content and the options, so rerunning the
//! conformance report only pays for POV-Ray when a scene or the options change.

use std::path::{Path, PathBuf};

/// 64-bit FNV-1a: stable across Rust versions and machines, unlike `DefaultHasher`, which
/// matters because the key names files that outlive the build that wrote them.
pub fn fnv64(parts: &[&[u8]]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for part in parts {
        for &b in *part {
            h ^= u64::from(b);
            h = h.wrapping_mul(0x0000_0100_0000_01b3);
        }
        // A separator so ("ab", "c") and ("a", "bc") differ.
        h ^= 0xff;
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    h
}

/// What POV-Ray did with one scene.
#[derive(Clone, Debug, PartialEq)]
pub struct PovResult {
    pub status: PovStatus,
    /// Wall time of the whole process, start-up included.
    pub seconds: f64,
    /// POV-Ray's own parse + bounding + photon + radiosity + trace times.
    pub work_seconds: f64,
    /// POV-Ray's first error line when it failed.
    pub message: String,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PovStatus {
    Ok,
    Failed,
    TimedOut,
}

impl PovStatus {
    fn as_str(self) -> &'static str {
        match self {
            PovStatus::Ok => "ok",
            PovStatus::Failed => "failed",
            PovStatus::TimedOut => "timeout",
        }
    }
}

pub struct Cache {
    dir: PathBuf,
}

impl Cache {
    pub fn new(dir: PathBuf) -> Result<Cache, String> {
        std::fs::create_dir_all(&dir)
            .map_err(|e| format!("cannot create the cache {}: {e}", dir.display()))?;
        Ok(Cache { dir })
    }

    pub fn picture(&self, key: u64) -> PathBuf {
        self.dir.join(format!("{key:016x}.png"))
    }

    fn record(&self, key: u64) -> PathBuf {
        self.dir.join(format!("{key:016x}.txt"))
    }

    pub fn get(&self, key: u64) -> Option<PovResult> {
        let text = std::fs::read_to_string(self.record(key)).ok()?;
        let mut f = text.trim_end_matches('\n').splitn(4, '\t');
        let status = match f.next()? {
            "ok" => PovStatus::Ok,
            "failed" => PovStatus::Failed,
            "timeout" => PovStatus::TimedOut,
            _ => return None,
        };
        let seconds = f.next()?.parse().ok()?;
        let work_seconds = f.next()?.parse().ok()?;
        let message = f.next().unwrap_or("").to_string();
        if status == PovStatus::Ok && !self.picture(key).exists() {
            return None;
        }
        Some(PovResult {
            status,
            seconds,
            work_seconds,
            message,
        })
    }

    /// Stores the record last, through a temporary name, so an interrupted run never leaves a
    /// record that claims a picture which is not there.
    pub fn put(&self, key: u64, r: &PovResult) -> Result<(), String> {
        let line = format!(
            "{}\t{:.3}\t{:.3}\t{}\n",
            r.status.as_str(),
            r.seconds,
            r.work_seconds,
            r.message.replace(['\t', '\n'], " ")
        );
        crate::output::write_text_atomic(&self.record(key), &line)
    }
}

/// The default cache location: `$LANCER_CONFORMANCE_CACHE`, else `$XDG_CACHE_HOME` or
/// `~/.cache`, under `lancer/conformance`.
pub fn default_dir() -> PathBuf {
    if let Some(d) = std::env::var_os("LANCER_CONFORMANCE_CACHE") {
        return PathBuf::from(d);
    }
    let base = std::env::var_os("XDG_CACHE_HOME")
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| Path::new(&h).join(".cache")))
        .unwrap_or_else(std::env::temp_dir);
    base.join("lancer").join("conformance")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn key_depends_on_every_part_and_its_boundaries() {
        assert_ne!(fnv64(&[b"ab", b"c"]), fnv64(&[b"a", b"bc"]));
        assert_ne!(fnv64(&[b"scene", b"+W160"]), fnv64(&[b"scene", b"+W320"]));
        assert_eq!(fnv64(&[b"x"]), fnv64(&[b"x"]));
    }

    #[test]
    fn round_trip_and_missing_picture() {
        let dir = std::env::temp_dir().join(format!("lancer-cache-test-{}", std::process::id()));
        let c = Cache::new(dir.clone()).unwrap();
        let failed = PovResult {
            status: PovStatus::Failed,
            seconds: 0.5,
            work_seconds: 0.0,
            message: "Parse Error:\tbad".into(),
        };
        c.put(1, &failed).unwrap();
        let back = c.get(1).unwrap();
        assert_eq!(back.status, PovStatus::Failed);
        assert_eq!(back.message, "Parse Error: bad");
        // An "ok" record without its picture is not trusted.
        let ok = PovResult {
            status: PovStatus::Ok,
            seconds: 1.0,
            work_seconds: 0.2,
            message: String::new(),
        };
        c.put(2, &ok).unwrap();
        assert!(c.get(2).is_none());
        let _ = std::fs::remove_dir_all(dir);
    }
}
