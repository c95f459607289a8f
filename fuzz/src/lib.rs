//! What the fuzz targets share: turning libFuzzer's bytes into scene text, and the filter that
//! keeps inputs away from the file system.
//!
//! Bytes become text with `String::from_utf8_lossy`, exactly as `Parser::load` reads a scene
//! file, so invalid UTF-8 reaches the lexer as U+FFFD the way it would from disk.
//!
//! Inputs that could open files are skipped: `#include` searches the current directory, the
//! system include directories and absolute paths (`/dev/stdin` would block, `/dev/zero` would
//! read without end), and `image_map` loads pictures. Skipping them keeps runs reproducible and
//! fast; the cost is that the include and image-map code paths are not fuzzed. `fopen` is in
//! the list for when `#fopen`/`#write` exist, so the fuzzer can never write files.

/// Words whose presence makes an input able to touch the file system.
const FILE_WORDS: &[&[u8]] = &[b"include", b"image_map", b"fopen"];

/// The scene text for `data`, or `None` when the input is skipped (see the module docs).
pub fn scene_text(data: &[u8]) -> Option<String> {
    if FILE_WORDS
        .iter()
        .any(|w| data.windows(w.len()).any(|x| x == *w))
    {
        return None;
    }
    Some(String::from_utf8_lossy(data).into_owned())
}

/// Parses `data` as a whole scene with default options (no library paths) and a loop cap, so
/// an endless `#while` (a valid scene) ends in an error instead of a libFuzzer timeout and
/// real hangs stand out. Errors are the expected outcome for most inputs; only panics, stack
/// overflows and hangs are findings.
pub fn parse(data: &[u8]) {
    let Some(text) = scene_text(data) else {
        return;
    };
    let mut p = lancer::sdl::Parser::new(lancer::sdl::ParseOptions {
        max_loop_iterations: Some(100_000),
        ..lancer::sdl::ParseOptions::default()
    });
    let _ = p.parse_str("fuzz.pov", &text);
}
