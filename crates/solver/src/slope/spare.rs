//! A thread's spare vectors: a search cuts and solves thousands of surfaces one after the other
//! on each thread, and each one's vectors (slice sides, slices, surface, slice terms, kernel
//! blocks) would otherwise be allocated and freed every time. A vector no longer needed is
//! kept ([`keep`]) as its thread's spare of that kind, and the next one takes it back
//! ([`take`]), emptied, with its capacity; the spare is as large as the largest such vector
//! the thread has made.

use std::cell::Cell;
use std::thread::LocalKey;

/// A thread's spare vector of one kind (`thread_local!`, `const { Cell::new(Vec::new()) }`).
pub(crate) type Spare<T> = LocalKey<Cell<Vec<T>>>;

/// The thread's spare vector of this kind, emptied (a new one if there is none).
#[inline]
pub(crate) fn take<T>(spare: &'static Spare<T>) -> Vec<T> {
    let mut vector = spare.take();
    vector.clear();
    vector
}

/// Keeps `vector` as the thread's spare of this kind (in place of any kept before).
#[inline]
pub(crate) fn keep<T>(spare: &'static Spare<T>, vector: Vec<T>) {
    spare.set(vector);
}
