//! Run statistics that the phase timings in lancer's summary line need from the system: the
//! peak resident memory, and a teardown that costs nothing when the process is about to end.

/// The process's peak resident set size so far (Linux `VmHWM`), None where unknown.
pub fn peak_rss_bytes() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024)
}

/// Memory the system can give without swapping (Linux `MemAvailable`), None where unknown.
pub fn available_memory_bytes() -> Option<u64> {
    let info = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = info.lines().find(|l| l.starts_with("MemAvailable:"))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024)
}

/// Drops `value`, unless `exiting`: then it is leaked, because freeing a scene of a million
/// objects one allocation at a time takes seconds that the operating system saves by taking
/// the whole address space back at exit.
pub fn dispose<T>(value: T, exiting: bool) {
    if exiting {
        std::mem::forget(value);
    } else {
        drop(value);
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn peak_memory_is_known_on_linux() {
        if cfg!(target_os = "linux") {
            let peak = super::peak_rss_bytes().expect("VmHWM in /proc/self/status");
            assert!(peak > 0);
        }
    }
}
