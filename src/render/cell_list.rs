//! A list of at most `M` copyable values kept on the stack with nothing written to its unused
//! slots: the noise lattice's hash walks (one cell per octave or sample, all walked before
//! any arithmetic) used arrays of `Option`s, which the compiler zero-filled whole on every
//! call (a 1,120-byte `memset` per vector turbulence, 1 % of a wood scene by instructions)
//! to fill three or four of their ten slots.

use std::mem::MaybeUninit;

/// Up to `M` values of a `Copy` type, pushed in order and read back as a slice.
pub(super) struct CellList<T: Copy, const M: usize> {
    buf: [MaybeUninit<T>; M],
    len: usize,
}

impl<T: Copy, const M: usize> CellList<T, M> {
    #[inline(always)]
    pub(super) fn new() -> Self {
        Self {
            // A constant, not `[MaybeUninit::uninit(); M]`: that repeat of a call's result
            // was compiled to a loop of stores that became a `memset` of the whole buffer.
            buf: [const { MaybeUninit::uninit() }; M],
            len: 0,
        }
    }

    /// Appends `v`; panics past `M` values (a bounds check, as an array's index would).
    #[inline(always)]
    pub(super) fn push(&mut self, v: T) {
        self.buf[self.len].write(v);
        self.len += 1;
    }

    /// The values pushed so far, in order.
    #[inline(always)]
    pub(super) fn as_slice(&self) -> &[T] {
        // SAFETY: `push` wrote the first `len` slots (and `len` never passes `M`, the index
        // there being checked); `MaybeUninit<T>` has `T`'s layout, so they read as `[T]`.
        unsafe { std::slice::from_raw_parts(self.buf.as_ptr() as *const T, self.len) }
    }
}

#[cfg(test)]
mod tests {
    use super::CellList;

    #[test]
    fn reads_back_what_was_pushed_in_order() {
        let mut l = CellList::<[u32; 3], 4>::new();
        assert!(l.as_slice().is_empty());
        for k in 0..4 {
            l.push([k, k + 1, k + 2]);
        }
        assert_eq!(l.as_slice(), &[[0, 1, 2], [1, 2, 3], [2, 3, 4], [3, 4, 5]]);
    }

    #[test]
    #[should_panic]
    fn refuses_more_than_its_capacity() {
        let mut l = CellList::<u8, 2>::new();
        for k in 0..3 {
            l.push(k);
        }
    }
}
