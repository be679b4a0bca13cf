//! Placeholder, replaced once the io::parse API is settled.
#![no_main]
use libfuzzer_sys::fuzz_target;
fuzz_target!(|_data: &[u8]| {});
