//! The CPU features of the paths chosen at run time (AVX, FMA), read with one `cpuid` and
//! one `xgetbv` on first use. `is_x86_feature_detected!` answers the same, but its first
//! call runs std's whole detection, about ten `cpuid` leaves; in a virtual machine each
//! `cpuid` traps to the hypervisor, and those ten were ~2 % of a small scene's process
//! (incdemo/strings, 3 ms).

/// Bits of `cpuid` leaf 1's ECX.
#[cfg(target_arch = "x86_64")]
mod ecx {
    pub const FMA: u32 = 1 << 12;
    pub const XSAVE: u32 = 1 << 26;
    pub const OSXSAVE: u32 = 1 << 27;
    pub const AVX: u32 = 1 << 28;
}

/// Unknown until the first query, then `KNOWN` with the features' bits.
#[cfg(target_arch = "x86_64")]
static FEATURES: std::sync::atomic::AtomicU8 = std::sync::atomic::AtomicU8::new(0);

#[cfg(target_arch = "x86_64")]
const KNOWN: u8 = 1;
#[cfg(target_arch = "x86_64")]
const HAS_AVX: u8 = 2;
#[cfg(target_arch = "x86_64")]
const HAS_FMA: u8 = 4;

/// Whether the CPU and the OS support AVX (std's `is_x86_feature_detected!("avx")`).
#[inline]
pub fn avx() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        features() & HAS_AVX != 0
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

/// Whether the CPU and the OS support FMA (std's `is_x86_feature_detected!("fma")`).
#[inline]
pub fn fma() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        features() & HAS_FMA != 0
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

#[cfg(target_arch = "x86_64")]
#[inline]
fn features() -> u8 {
    use std::sync::atomic::Ordering;
    let f = FEATURES.load(Ordering::Relaxed);
    if f & KNOWN != 0 {
        return f;
    }
    let f = query();
    FEATURES.store(f, Ordering::Relaxed);
    f
}

/// std's rule: AVX and FMA count only where the OS saves the YMM registers (XSAVE and
/// OSXSAVE set, and XCR0 enabling both the SSE and the AVX state).
#[cfg(target_arch = "x86_64")]
#[cold]
fn query() -> u8 {
    let c = std::arch::x86_64::__cpuid(1).ecx;
    if c & ecx::XSAVE == 0 || c & ecx::OSXSAVE == 0 {
        return KNOWN;
    }
    let xcr0_low: u32;
    // SAFETY: OSXSAVE set means the OS has enabled `xgetbv`; register 0 always exists.
    unsafe {
        std::arch::asm!(
            "xgetbv",
            in("ecx") 0u32,
            out("eax") xcr0_low,
            out("edx") _,
            options(nomem, nostack, preserves_flags),
        );
    }
    if xcr0_low & 6 != 6 {
        return KNOWN;
    }
    let mut f = KNOWN;
    if c & ecx::AVX != 0 {
        f |= HAS_AVX;
    }
    if c & ecx::FMA != 0 {
        f |= HAS_FMA;
    }
    f
}

#[cfg(test)]
mod tests {
    #[test]
    fn features_are_what_std_detects() {
        #[cfg(target_arch = "x86_64")]
        {
            assert_eq!(super::avx(), std::arch::is_x86_feature_detected!("avx"));
            assert_eq!(super::fma(), std::arch::is_x86_feature_detected!("fma"));
            // Cached: the same answer again.
            assert_eq!(super::avx(), std::arch::is_x86_feature_detected!("avx"));
        }
    }
}
