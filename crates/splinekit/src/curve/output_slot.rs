//! Where a batch evaluation writes its values: into points already there, or into memory
//! not yet written (a new array, e.g. numpy's), through one kernel.
//!
//! [`Curve::eval_many`](crate::curve::Curve::eval_many) writes `&mut [Point<D>]`; a caller
//! with fresh memory would have to zero it first only so that the slice may exist. The
//! batch kernels are generic over the [`Slot`] they write (`*slot = v`, or
//! [`MaybeUninit::write`]), so [`Curve::eval_many_uninit`](crate::curve::Curve::eval_many_uninit)
//! writes the fresh memory once, with the same operations and so the same bits.

use std::mem::MaybeUninit;

use crate::Coefficient;

/// One output value of a batch: a `T` that is overwritten, or a `MaybeUninit<T>` that is
/// written for the first time.
pub trait Slot<T: Copy>: Sized {
    /// Stores `v`.
    fn put(&mut self, v: T);
    /// The slots as values of `T`: themselves, or, for memory not yet written, zeroed
    /// first (for the paths that have no slot-generic kernel).
    fn initialised(slots: &mut [Self]) -> &mut [T];
}

impl<T: Copy> Slot<T> for T {
    #[inline(always)]
    fn put(&mut self, v: T) {
        *self = v;
    }
    #[inline(always)]
    fn initialised(slots: &mut [T]) -> &mut [T] {
        slots
    }
}

impl<T: Coefficient> Slot<T> for MaybeUninit<T> {
    #[inline(always)]
    fn put(&mut self, v: T) {
        self.write(v);
    }
    fn initialised(slots: &mut [Self]) -> &mut [T] {
        zeroed(slots)
    }
}

/// `slots` with zero written into each, as values of `T`.
pub fn zeroed<T: Coefficient>(slots: &mut [MaybeUninit<T>]) -> &mut [T] {
    for s in slots.iter_mut() {
        s.write(T::zero());
    }
    // SAFETY: every slot was written just above; `MaybeUninit<T>` has `T`'s layout.
    unsafe { &mut *(slots as *mut [MaybeUninit<T>] as *mut [T]) }
}
