//! A hint to the processor that an array item will be read soon: for the sequential loops
//! whose order is fixed by the result (the pruning's leaves in order of radius) and whose
//! every step reads records scattered over arrays of hundreds of megabytes. Found a few
//! steps ahead, their fetches overlap the current step's work instead of each stalling it.
//!
//! The crate's one use of `unsafe`: the prefetch instruction is reached only through an
//! intrinsic that Rust declares unsafe, although it has no safety condition to uphold (it
//! reads nothing the program observes and does not fault on any address). It is confined
//! to this module; the rest of the crate is compiled with `unsafe_code` denied.
#![allow(unsafe_code)]

/// Asks the processor to bring `items[index]` into its caches; nothing when `index` is out
/// of range or on architectures other than x86-64 (where the prefetch intrinsic is not
/// stable Rust).
#[inline]
pub(crate) fn prefetch<T>(items: &[T], index: usize) {
    #[cfg(target_arch = "x86_64")]
    if let Some(item) = items.get(index) {
        use std::arch::x86_64::{_mm_prefetch, _MM_HINT_T0};
        // SAFETY: a prefetch has no observable effect but timing and never faults; `sse`,
        // which provides it, is part of every x86-64 target's baseline.
        unsafe { _mm_prefetch::<_MM_HINT_T0>(std::ptr::from_ref(item).cast::<i8>()) }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = (items, index);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A hint never reads or changes what it points at, in range or not.
    #[test]
    fn a_prefetch_changes_nothing() {
        let items = vec![[1u32, 2, 3]; 100];
        for index in [0, 50, 99, 100, usize::MAX] {
            prefetch(&items, index);
        }
        prefetch::<u8>(&[], 0);
        assert!(items.iter().all(|&i| i == [1, 2, 3]));
    }
}
