//! Links the `lancer` command as a position-dependent executable on Linux. A PIE of this size
//! carries about 19,000 relative relocations that the dynamic loader applies at every start,
//! writing (and so copying) every page of `.data.rel.ro` and the GOT: a sixth of a one-pixel
//! render's CPU time. Fixed at link time instead, they cost nothing. The code is the same (still
//! compiled position-independent), so are the pictures; only the command's load address is
//! no longer randomised. The Python module (a shared library) is not affected. Other systems'
//! linkers spell the flag differently (or not at all), so they keep their default.
fn main() {
    // Only this file decides the link flags: no rerun (and relink) when other files change.
    println!("cargo:rerun-if-changed=build.rs");
    let os = std::env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    let env = std::env::var("CARGO_CFG_TARGET_ENV").unwrap_or_default();
    if os == "linux" && env == "gnu" {
        println!("cargo:rustc-link-arg-bin=lancer=-no-pie");
    }
}
