//! The vectors of a cut's slices and surface, kept per thread from cut to cut: a search cuts
//! thousands of surfaces on each thread, and each takes the vectors the last one gave back.

use crate::slope::slices::BaseSlice;
use crate::slope::spare;

thread_local! {
    /// A searched cut's slices and surface, given back once it is solved ([`give_back`]).
    static SPARE_SLICES: std::cell::Cell<Vec<BaseSlice>> =
        const { std::cell::Cell::new(Vec::new()) };
    static SPARE_SURFACE: std::cell::Cell<Vec<(f64, f64)>> =
        const { std::cell::Cell::new(Vec::new()) };
}

/// Empty vectors for a cut's slices and surface, with room for `sides` sides (and a crack's
/// top): the thread's spares ([`spare`]).
pub(super) fn vectors(sides: usize) -> (Vec<BaseSlice>, Vec<(f64, f64)>) {
    let (mut slices, mut surface) = (spare::take(&SPARE_SLICES), spare::take(&SPARE_SURFACE));
    slices.reserve(sides.saturating_sub(1));
    surface.reserve(sides + 1);
    (slices, surface)
}

/// A cut's slices and surface, no longer needed, kept for the next cut on this thread.
pub(super) fn give_back(slices: Vec<BaseSlice>, surface: Vec<(f64, f64)>) {
    spare::keep(&SPARE_SLICES, slices);
    spare::keep(&SPARE_SURFACE, surface);
}
