//! The entry of a best-first search: an item ranked by a lower bound, smallest first.

use std::cmp::Ordering;

/// An item with the lower bound of what it can hold; [`std::collections::BinaryHeap`]
/// pops the smallest bound first.
#[derive(Debug, Clone)]
pub struct Ranked<T> {
    /// The lower bound.
    pub bound: f64,
    /// The item.
    pub item: T,
}

impl<T> PartialEq for Ranked<T> {
    fn eq(&self, other: &Self) -> bool {
        self.bound == other.bound
    }
}
impl<T> Eq for Ranked<T> {}
impl<T> PartialOrd for Ranked<T> {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl<T> Ord for Ranked<T> {
    /// Reversed, so that the max-heap pops the smallest bound first.
    fn cmp(&self, other: &Self) -> Ordering {
        other.bound.total_cmp(&self.bound)
    }
}
