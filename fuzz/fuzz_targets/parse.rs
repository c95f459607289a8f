//! libFuzzer target: arbitrary bytes parsed as a whole scene (see src/lib.rs for how bytes
//! become text and which inputs are skipped).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| lancer_fuzz::parse(data));
