//! What steers a parse from outside the scene: the image size, the animation clock, `#fopen`'s
//! permissions, loop limits, INI declares and the include-file search path.

use std::path::PathBuf;

/// Settings the scene language can see or that steer parsing.
#[derive(Clone, Debug)]
pub struct ParseOptions {
    /// Directories searched for `#include` and image files after the scene's own directory.
    pub library_paths: Vec<PathBuf>,
    pub image_width: u32,
    pub image_height: u32,
    /// Animation values the scene sees as `clock`, `clock_delta`, `clock_on`, `frame_number`,
    /// `initial_frame`, `final_frame`, `initial_clock` and `final_clock`. The defaults are
    /// POV-Ray's for a still picture: all zero, clock off.
    pub clock: f64,
    pub clock_delta: f64,
    pub clock_on: bool,
    pub frame_number: i64,
    pub initial_frame: i64,
    pub final_frame: i64,
    pub initial_clock: f64,
    pub final_clock: f64,
    /// Lets `#fopen` read and write anywhere; by default only below the scene's directory
    /// and the current directory (reads also in the library paths).
    pub io_unrestricted: bool,
    /// Further directories `#fopen` may read and write below.
    pub io_allowed_dirs: Vec<PathBuf>,
    /// povray.conf's `read-only` security: `#fopen` may read anywhere.
    pub io_read_anywhere: bool,
    /// povray.conf's `[Permitted Paths]`, beside the directories above.
    pub io_permits: Vec<crate::config::IoPermit>,
    /// Stops the parse with an error after this many `#while`/`#for` iterations in all;
    /// `None` (the default) lets loops run as long as they like, as POV-Ray does.
    pub max_loop_iterations: Option<u64>,
    /// `Declare=Name=Value` options: floats declared before the scene is read.
    pub declares: Vec<(String, f64)>,
    /// `Version=n.n` / `+MVn.n`: the language version before any `#version`.
    pub version: Option<f64>,
    /// `Include_Header=file` / `+HIfile`: included before the scene's first line.
    pub include_header: Option<String>,
}

impl Default for ParseOptions {
    fn default() -> Self {
        ParseOptions {
            library_paths: Vec::new(),
            image_width: 320,
            image_height: 240,
            clock: 0.0,
            clock_delta: 0.0,
            clock_on: false,
            frame_number: 0,
            initial_frame: 0,
            final_frame: 0,
            initial_clock: 0.0,
            final_clock: 0.0,
            io_unrestricted: false,
            io_allowed_dirs: Vec::new(),
            io_read_anywhere: false,
            io_permits: Vec::new(),
            max_loop_iterations: None,
            declares: Vec::new(),
            version: None,
            include_header: None,
        }
    }
}

/// The standard places Debian and source installs put POV-Ray's include files.
pub const SYSTEM_INCLUDE_DIRS: &[&str] = &[
    "/usr/share/povray-3.7/include",
    "/usr/local/share/povray-3.7/include",
    "/usr/share/povray/include",
    "/usr/local/share/povray/include",
];
