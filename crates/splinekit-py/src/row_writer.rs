//! New output arrays written row chunk by row chunk with the GIL released: the writer of
//! every batch evaluation of curves (`Curve.__call__`, `derivatives`, `evaluate_many`).
//!
//! The array is allocated like `numpy.empty` (numpy backs large arrays with huge pages).
//! A curve batch writes each chunk of [`CHUNK_ROWS`] rows once, through slots of memory
//! not yet written (`Curve::eval_many_uninit`); what cannot (a surface grid) gets its chunk
//! zeroed first, so that no reference to unwritten memory exists. (Evaluating each chunk
//! into a per-thread scratch and copying it out with streaming stores was tried: no faster
//! from Python, where the freed output of the previous call is usually still in the L3
//! cache; zeroing costs a second pass over the output.)

use std::mem::MaybeUninit;
use std::ops::Range;

use numpy::{PyArrayDyn, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::prelude::*;
use splinekit::curve::output_slot::zeroed;

/// Rows evaluated per chunk: the unit of work `evaluate_many` shares between threads, and
/// small enough that a zeroed chunk ([`RowWriter::write`]) stays in cache until it is
/// evaluated.
const CHUNK_ROWS: usize = 2048;

/// A raw pointer that may cross into the GIL-free closure (the array it points into is
/// kept alive by the caller and written by one thread).
struct SendPtr(*mut f64);
// SAFETY: used only by `RowWriter`, whose users write disjoint chunks (each by one
// thread) while the owning array is alive.
unsafe impl Send for SendPtr {}
unsafe impl Sync for SendPtr {}

impl SendPtr {
    /// The pointer (a method, so closures capture the wrapper and not the raw field).
    fn get(&self) -> *mut f64 {
        self.0
    }
}

/// A new C-contiguous float64 array of `shape` whose leading axis has `rows` rows of
/// `row_len` values, written by `fill(rows_range, chunk)` chunk by chunk with the GIL
/// released; `chunk` is not yet written, and `fill` must write every value of it.
pub fn filled_rows<'py>(
    py: Python<'py>,
    shape: &[usize],
    rows: usize,
    row_len: usize,
    fill: impl Fn(Range<usize>, &mut [MaybeUninit<f64>]) + Send + Sync,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let (out, writer) = unfilled_rows(py, shape, rows, row_len);
    py.detach(|| {
        for range in writer.chunks() {
            // SAFETY: each chunk range once, from this thread; `fill` writes every value
            // (its caller's promise).
            unsafe { writer.write_uninit(range.clone(), |chunk| fill(range, chunk)) };
        }
    });
    Ok(out)
}

/// A new C-contiguous float64 array of `shape` (leading axis `rows` rows of `row_len`
/// values) not yet written, and the [`RowWriter`] that writes it chunk by chunk (the
/// chunks of [`filled_rows`], so batch calls compute exactly what single calls do).
pub fn unfilled_rows<'py>(
    py: Python<'py>,
    shape: &[usize],
    rows: usize,
    row_len: usize,
) -> (Bound<'py, PyArrayDyn<f64>>, RowWriter) {
    // SAFETY: a new C-contiguous array of `rows · row_len` f64 (checked below); its
    // memory is only written, through `MaybeUninit` slots (`RowWriter::write_uninit`), never
    // read before it is.
    let out = unsafe { PyArrayDyn::<f64>::new(py, shape, false) };
    assert_eq!(out.len(), rows * row_len, "shape holds the rows");
    let writer = RowWriter { base: SendPtr(out.data()), rows, row_len };
    (out, writer)
}

/// Writes the rows of a new array (from [`unfilled_rows`]) in chunks of [`CHUNK_ROWS`] rows,
/// from any thread, the GIL released; the caller keeps the array alive meanwhile.
pub struct RowWriter {
    base: SendPtr,
    rows: usize,
    row_len: usize,
}

impl RowWriter {
    /// The row ranges of the chunks, in order.
    pub fn chunks(&self) -> impl Iterator<Item = Range<usize>> + use<> {
        let rows = self.rows;
        (0..rows).step_by(CHUNK_ROWS).map(move |start| start..(start + CHUNK_ROWS).min(rows))
    }

    /// Writes the rows `range` by `fill`, which receives them not yet written and must
    /// write every value (as [`splinekit::curve::Curve::eval_many_uninit`] does): the
    /// memory is written once.
    ///
    /// # Safety
    /// As for [`RowWriter::write`]; and `fill` writes every value.
    pub unsafe fn write_uninit(&self, range: Range<usize>, fill: impl FnOnce(&mut [MaybeUninit<f64>])) {
        assert!(range.start <= range.end && range.end <= self.rows, "rows of the array");
        let len = range.len() * self.row_len;
        // SAFETY: inside the array (asserted), not written by anyone else (the caller's
        // promise); slots of `MaybeUninit` may hold unwritten memory.
        let chunk = unsafe {
            let target = self.base.get().add(range.start * self.row_len);
            std::slice::from_raw_parts_mut(target.cast::<MaybeUninit<f64>>(), len)
        };
        fill(chunk);
    }

    /// Writes the rows `range` by `fill`, which receives their values zeroed (for what
    /// cannot write through slots, a surface grid).
    ///
    /// # Safety
    /// `range` lies within the rows, the array is alive, and no other thread writes these
    /// rows meanwhile (each chunk is written once, by one thread).
    pub unsafe fn write(&self, range: Range<usize>, fill: impl FnOnce(&mut [f64])) {
        // SAFETY: the caller's promise; every value is written (zero) before `fill` runs.
        unsafe { self.write_uninit(range, |chunk| fill(zeroed(chunk))) }
    }
}
