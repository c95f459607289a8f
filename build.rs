//! Link settings of the `lancer` command on Linux with glibc, both for its start-up time.
//!
//! Position-dependent executable: a PIE of this size carries about 19,000 relative relocations
//! that the dynamic loader applies at every start, writing (and so copying) every page of
//! `.data.rel.ro` and the GOT: a sixth of a one-pixel render's CPU time. Fixed at link time
//! instead, they cost nothing. The code is the same (still compiled position-independent), so
//! are the pictures; only the command's load address is no longer randomised. The Python
//! module (a shared library) is not affected. Other systems' linkers spell the flag
//! differently (or not at all), so they keep their default.
//!
//! The unwinder linked in, not loaded: std asks for `libgcc_s.so.1` only for the `_Unwind_*`
//! functions (panics and backtraces), and loading it runs its constructor
//! `__cpu_indicator_init`, whose `cpuid` leaves each exit to the hypervisor on a virtual
//! machine: with the mapping and symbol binding ~0.24 ms of every run (a hello-world program:
//! 1.07 ms task-clock against 0.83 ms). The same unwinder is in GCC's static `libgcc_eh.a`,
//! which std itself links for `crt-static` builds; a linker script named `libgcc_s.so` in
//! `OUT_DIR`, searched before the system's directories, hands the linker that archive for
//! std's `-lgcc_s`. Only when the C compiler that links (`cc`) names an existing archive;
//! otherwise the shared library is linked as before.
use std::path::{Path, PathBuf};
use std::process::Command;

fn main() {
    // Only this file decides the link flags: no rerun (and relink) when other files change.
    println!("cargo:rerun-if-changed=build.rs");
    let os = std::env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    let env = std::env::var("CARGO_CFG_TARGET_ENV").unwrap_or_default();
    if os == "linux" && env == "gnu" {
        println!("cargo:rustc-link-arg-bin=lancer=-no-pie");
        if let (Some(eh), Some(out)) = (static_unwinder(), std::env::var_os("OUT_DIR")) {
            let dir = PathBuf::from(out).join("unwind");
            let script = format!("INPUT({})\n", eh.display());
            if std::fs::create_dir_all(&dir).is_ok()
                && std::fs::write(dir.join("libgcc_s.so"), script).is_ok()
            {
                println!("cargo:rustc-link-search=native={}", dir.display());
            }
        }
    }
}

/// The absolute path of GCC's `libgcc_eh.a` as the linking C compiler reports it, if the file
/// exists (`-print-file-name` echoes a bare name it cannot find).
fn static_unwinder() -> Option<PathBuf> {
    // A cross or custom linker may be another compiler whose archive does not match.
    if std::env::var("TARGET").ok() != std::env::var("HOST").ok() {
        return None;
    }
    let out = Command::new("cc")
        .arg("-print-file-name=libgcc_eh.a")
        .output()
        .ok()?;
    let path = PathBuf::from(String::from_utf8(out.stdout).ok()?.trim());
    // A path with a ')' or a newline would break the script's INPUT(...).
    let plain = path.to_str().is_some_and(|s| !s.contains([')', '\n', ' ']));
    (out.status.success() && plain && path.is_absolute() && Path::new(&path).is_file())
        .then_some(path)
}
