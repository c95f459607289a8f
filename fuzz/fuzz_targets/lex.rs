//! libFuzzer target: the lexer alone, so tokenising bugs are found without the parser's
//! (much slower) work in the way. No file access is possible here, so nothing is skipped.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let _ = lancer::sdl::lexer::lex(&text, 0);
});
