//! POV-Ray's configuration files, read from the places POV-Ray 3.7 for Unix reads them so that
//! `lancer scene.pov` writes what `povray scene.pov` writes on the same machine.
//!
//! The main INI file (POV-Ray manual, Unix section 1.5.2) is the first that exists of: the file
//! named by `POVINI`, `./povray.ini`, `$HOME/.povray/3.7/povray.ini`, the system directory's
//! `povray.ini` (Debian: /etc/povray/3.7), then the deprecated `$HOME/.povrayrc` and
//! `/etc/povray.ini`. Measured with Debian's povray 3.7 (a temporary HOME, POVINI and working
//! directory): only the first file found is read; a `POVINI` naming a missing file is reported
//! ("POVINI environment: cannot open ...") and the search goes on. Its options come before the
//! command line's, so the command line wins.
//!
//! The I/O restrictions (manual section 1.4) come from the system `povray.conf` and
//! `$HOME/.povray/3.7/povray.conf`; where both exist the stricter setting wins. lancer never
//! runs shell commands, whatever `[Shellout Security]` says.
//!
//! `--no-config` or `LANCER_NO_CONFIG=1` reads none of these files: the conformance runner,
//! the tests and the scripts use it so their results do not depend on the machine.

use std::path::{Path, PathBuf};

/// Where POV-Ray 3.7 as Debian builds it keeps its system configuration.
pub const SYSTEM_DIR: &str = "/etc/povray/3.7";
/// What `%INSTALLDIR%` stands for in povray.conf on Debian.
pub const INSTALL_DIR: &str = "/usr/share/povray-3.7";
/// The environment variable that turns configuration files off.
pub const NO_CONFIG_ENV: &str = "LANCER_NO_CONFIG";

/// The places the configuration is looked for; `from_env` fills them as povray would.
#[derive(Clone, Debug)]
pub struct Places {
    /// `POVINI`, if set.
    pub povini: Option<PathBuf>,
    pub home: Option<PathBuf>,
    pub cwd: PathBuf,
    pub system_dir: PathBuf,
    /// The deprecated system-wide `povray.ini` of 3.5.
    pub old_system_ini: PathBuf,
    pub install_dir: PathBuf,
}

impl Places {
    pub fn from_env() -> Places {
        Places {
            povini: std::env::var_os("POVINI")
                .filter(|v| !v.is_empty())
                .map(PathBuf::from),
            home: std::env::var_os("HOME")
                .filter(|v| !v.is_empty())
                .map(PathBuf::from),
            cwd: std::env::current_dir().unwrap_or_else(|_| PathBuf::from(".")),
            system_dir: PathBuf::from(SYSTEM_DIR),
            old_system_ini: PathBuf::from("/etc/povray.ini"),
            install_dir: PathBuf::from(INSTALL_DIR),
        }
    }

    fn user_dir(&self) -> Option<PathBuf> {
        self.home.as_ref().map(|h| h.join(".povray").join("3.7"))
    }
}

/// Whether configuration files are off for this run: `--no-config` among the arguments or
/// `LANCER_NO_CONFIG` set to anything but empty or `0`.
pub fn disabled(args: &[String]) -> bool {
    args.iter().skip(1).any(|a| a == "--no-config")
        || std::env::var(NO_CONFIG_ENV).is_ok_and(|v| !v.is_empty() && v != "0")
}

/// The main INI file povray would read, and warnings about the search.
pub fn main_ini(p: &Places, warnings: &mut Vec<String>) -> Option<PathBuf> {
    if let Some(ini) = &p.povini {
        let ini = p.cwd.join(ini);
        if ini.is_file() {
            return Some(ini);
        }
        warnings.push(format!(
            "POVINI environment: cannot open {}: no such file",
            ini.display()
        ));
    }
    let mut places = vec![p.cwd.join("povray.ini")];
    places.extend(p.user_dir().map(|d| d.join("povray.ini")));
    places.push(p.system_dir.join("povray.ini"));
    places.extend(p.home.as_ref().map(|h| h.join(".povrayrc")));
    places.push(p.old_system_ini.clone());
    places.into_iter().find(|f| f.is_file())
}

/// `[File I/O Security]`, from least to most strict.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Default)]
pub enum IoSecurity {
    #[default]
    None,
    ReadOnly,
    Restricted,
}

/// A `[Permitted Paths]` entry.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct IoPermit {
    pub dir: PathBuf,
    pub write: bool,
    /// `read*=` / `read+write*=`: the subdirectories too.
    pub subdirs: bool,
}

/// What povray.conf files amount to. With no file at all POV-Ray restricts nothing, but lancer
/// keeps its own default (the scene's and the current directory), so no file means `None`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct IoConf {
    pub security: IoSecurity,
    pub permits: Vec<IoPermit>,
    /// The files read, for messages.
    pub files: Vec<PathBuf>,
}

/// Reads the system and the user povray.conf; `None` when neither exists.
pub fn io_conf(p: &Places, warnings: &mut Vec<String>) -> Option<IoConf> {
    let mut files = vec![p.system_dir.join("povray.conf")];
    files.extend(p.user_dir().map(|d| d.join("povray.conf")));
    let mut conf: Option<IoConf> = None;
    for f in files.into_iter().filter(|f| f.is_file()) {
        let text = match std::fs::read_to_string(&f) {
            Ok(t) => t,
            Err(e) => {
                warnings.push(format!("cannot read {}: {e}", f.display()));
                continue;
            }
        };
        let one = parse_conf(&text, &f, p, warnings);
        conf = Some(match conf {
            None => one,
            // User settings can only make security stricter: the stricter level, and a path
            // permitted only when both files permit it (POV-Ray asks the user file to repeat
            // the system's paths for the same reason).
            Some(mut c) => {
                c.security = c.security.max(one.security);
                if one.security != IoSecurity::None {
                    c.permits = c
                        .permits
                        .iter()
                        .filter_map(|a| {
                            let b = one.permits.iter().find(|b| b.dir == a.dir)?;
                            Some(IoPermit {
                                dir: a.dir.clone(),
                                write: a.write && b.write,
                                subdirs: a.subdirs && b.subdirs,
                            })
                        })
                        .collect();
                }
                c.files.extend(one.files);
                c
            }
        });
    }
    conf
}

fn parse_conf(text: &str, file: &Path, p: &Places, warnings: &mut Vec<String>) -> IoConf {
    let mut conf = IoConf {
        files: vec![file.to_path_buf()],
        ..IoConf::default()
    };
    let mut section = String::new();
    for (n, raw) in text.lines().enumerate() {
        let line = raw.split(';').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let place = format!("{}:{}", file.display(), n + 1);
        if let Some(s) = line.strip_prefix('[').and_then(|l| l.strip_suffix(']')) {
            section = s.trim().to_ascii_lowercase();
            continue;
        }
        match section.as_str() {
            "file i/o security" => match line.to_ascii_lowercase().as_str() {
                "none" => conf.security = IoSecurity::None,
                "read-only" => conf.security = IoSecurity::ReadOnly,
                "restricted" => conf.security = IoSecurity::Restricted,
                other => warnings.push(format!(
                    "{place}: unknown I/O security '{other}' (none, read-only or restricted)"
                )),
            },
            // Shell-outs are never run by lancer; nothing to configure.
            "shellout security" => {}
            "permitted paths" => match permit(line, p) {
                Some(pm) => conf.permits.push(pm),
                None => warnings.push(format!(
                    "{place}: expected read=dir or read+write=dir, found '{line}'"
                )),
            },
            _ => warnings.push(format!("{place}: '{line}' outside a known section")),
        }
    }
    conf
}

fn permit(line: &str, p: &Places) -> Option<IoPermit> {
    let (key, value) = line.split_once('=')?;
    let key = key.trim().to_ascii_lowercase();
    let (kind, subdirs) = match key.strip_suffix('*') {
        Some(k) => (k.trim(), true),
        None => (key.as_str(), false),
    };
    let write = match kind {
        "read" => false,
        "read+write" => true,
        _ => return None,
    };
    let value = value.trim();
    let value = value
        .strip_prefix('"')
        .and_then(|v| v.strip_suffix('"'))
        .or_else(|| value.strip_prefix('\'').and_then(|v| v.strip_suffix('\'')))
        .unwrap_or(value);
    let home = p
        .home
        .as_ref()
        .map(|h| h.display().to_string())
        .unwrap_or_default();
    let value = value
        .replace("%INSTALLDIR%", &p.install_dir.display().to_string())
        .replace("%HOME%", &home);
    // Relative paths are resolved once, against the directory povray started in.
    Some(IoPermit {
        dir: p.cwd.join(value),
        write,
        subdirs,
    })
}

/// The configuration a render starts from.
#[derive(Clone, Debug, Default)]
pub struct Config {
    /// The main INI file's options as switches, applied before the command line's.
    pub switches: Vec<String>,
    pub ini: Option<PathBuf>,
    pub io: Option<IoConf>,
}

/// Reads the main INI file and povray.conf as povray would from `places`.
pub fn load(places: &Places, warnings: &mut Vec<String>) -> Result<Config, String> {
    let ini = main_ini(places, warnings);
    let switches = match &ini {
        Some(f) => crate::ini::expand_file(f, warnings)?,
        None => Vec::new(),
    };
    Ok(Config {
        switches,
        ini,
        io: io_conf(places, warnings),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn places(root: &Path) -> Places {
        Places {
            povini: None,
            home: Some(root.join("home")),
            cwd: root.join("cwd"),
            system_dir: root.join("etc"),
            old_system_ini: root.join("old.ini"),
            install_dir: PathBuf::from("/inst"),
        }
    }

    fn tree(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("lancer-config-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        for sub in ["home/.povray/3.7", "cwd", "etc"] {
            std::fs::create_dir_all(d.join(sub)).unwrap();
        }
        d
    }

    #[test]
    fn first_main_ini_found_wins_as_povray_searches() {
        let d = tree("ini");
        let p = places(&d);
        let mut w = Vec::new();
        assert_eq!(main_ini(&p, &mut w), None);
        std::fs::write(d.join("old.ini"), "Width=1\n").unwrap();
        assert_eq!(main_ini(&p, &mut w), Some(d.join("old.ini")));
        std::fs::write(d.join("home/.povrayrc"), "Width=2\n").unwrap();
        assert_eq!(main_ini(&p, &mut w), Some(d.join("home/.povrayrc")));
        std::fs::write(d.join("etc/povray.ini"), "Width=3\n").unwrap();
        assert_eq!(main_ini(&p, &mut w), Some(d.join("etc/povray.ini")));
        let user = d.join("home/.povray/3.7/povray.ini");
        std::fs::write(&user, "Width=4\n").unwrap();
        assert_eq!(main_ini(&p, &mut w), Some(user));
        std::fs::write(d.join("cwd/povray.ini"), "Width=5\n").unwrap();
        assert_eq!(main_ini(&p, &mut w), Some(d.join("cwd/povray.ini")));
        assert!(w.is_empty());
        // A POVINI naming no file is reported and the search goes on, as povray does.
        let mut q = p.clone();
        q.povini = Some(d.join("nope.ini"));
        assert_eq!(main_ini(&q, &mut w), Some(d.join("cwd/povray.ini")));
        assert!(w[0].contains("POVINI"), "{w:?}");
        std::fs::write(d.join("mine.ini"), "Width=6\n").unwrap();
        q.povini = Some(d.join("mine.ini"));
        let c = load(&q, &mut w).unwrap();
        assert_eq!(c.switches, vec!["+W6"]);
    }

    #[test]
    fn povray_conf_stricter_wins() {
        let d = tree("conf");
        let p = places(&d);
        let mut w = Vec::new();
        assert_eq!(io_conf(&p, &mut w), None);
        std::fs::write(
            d.join("etc/povray.conf"),
            "; Debian's\n[File I/O Security]\nread-only ; comment\n[Shellout Security]\nforbidden\n[Permitted Paths]\nread* = %INSTALLDIR%/include\nread* = %HOME%\nread+write* = /tmp\nread+write  = .\nread* = \"/a b\"\n",
        )
        .unwrap();
        let c = io_conf(&p, &mut w).unwrap();
        assert!(w.is_empty(), "{w:?}");
        assert_eq!(c.security, IoSecurity::ReadOnly);
        let dirs: Vec<_> = c.permits.iter().map(|p| p.dir.clone()).collect();
        assert_eq!(
            dirs,
            vec![
                PathBuf::from("/inst/include"),
                d.join("home"),
                PathBuf::from("/tmp"),
                d.join("cwd/."),
                PathBuf::from("/a b")
            ]
        );
        assert!(c.permits[2].write && c.permits[2].subdirs);
        assert!(c.permits[3].write && !c.permits[3].subdirs);
        // The user's file can make things stricter, never looser.
        std::fs::write(
            d.join("home/.povray/3.7/povray.conf"),
            "[File I/O Security]\nnone\n",
        )
        .unwrap();
        assert_eq!(io_conf(&p, &mut w).unwrap().security, IoSecurity::ReadOnly);
        std::fs::write(
            d.join("home/.povray/3.7/povray.conf"),
            "[File I/O Security]\nrestricted\n[Permitted Paths]\nread = /tmp\n",
        )
        .unwrap();
        let c = io_conf(&p, &mut w).unwrap();
        assert_eq!(c.security, IoSecurity::Restricted);
        let tmp = IoPermit {
            dir: PathBuf::from("/tmp"),
            write: false,
            subdirs: false,
        };
        assert_eq!(c.permits, vec![tmp]);
    }
}
