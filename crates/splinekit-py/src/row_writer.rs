//! New output arrays written row chunk by row chunk with the GIL released: the writer of
//! every batch evaluation of curves (`Curve.__call__`, `derivatives`, `evaluate_many`).
//!
//! The array is allocated like `numpy.empty` and never read before it is written. A chunk
//! of [`CHUNK_ROWS`] rows is evaluated either in place (zeroed first, so no reference to
//! unwritten memory exists), or, for outputs of [`STREAM_BYTES`] or more, into a zeroed
//! per-thread scratch chunk that stays in cache, then copied to the array with streaming
//! stores. A large output cannot stay in cache anyway, and streaming stores write it once
//! without first reading every line of it into the cache (the in-place path reads each
//! line for the zeroing, then writes it twice). For 10⁶ points of a cubic 3-D B-spline
//! this takes a quarter off the time of a call (README, "Speed", Python row). Both paths
//! write the same values: the kernel's, bit for bit.

use std::cell::RefCell;
use std::ops::Range;

use numpy::{PyArrayDyn, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::prelude::*;

/// Rows evaluated per chunk: small enough that a chunk stays in cache between its zeroing
/// and its evaluation (or in the scratch between its evaluation and its copy).
const CHUNK_ROWS: usize = 2048;

/// Outputs of this many bytes or more are written through the scratch with streaming
/// stores: well past a core's 1 MB L2 cache, where the output would not stay in cache.
/// Smaller outputs are written in place and are still in cache for what reads them next.
const STREAM_BYTES: usize = 4 << 20;

/// Chunks of more values than this are written in place whatever the output's size (a
/// surface grid is one chunk of all its sites; no scratch of that size is kept).
const SCRATCH_VALUES: usize = 1 << 17;

thread_local! {
    /// Each thread's scratch chunk, kept between chunks and calls.
    static SCRATCH: RefCell<Vec<f64>> = const { RefCell::new(Vec::new()) };
}

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
/// released; `chunk` starts zeroed.
pub fn filled_rows<'py>(
    py: Python<'py>,
    shape: &[usize],
    rows: usize,
    row_len: usize,
    fill: impl Fn(Range<usize>, &mut [f64]) + Send + Sync,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let (out, writer) = unfilled_rows(py, shape, rows, row_len);
    py.detach(|| {
        for range in writer.chunks() {
            // SAFETY: each chunk range once, from this thread.
            unsafe { writer.write(range.clone(), |chunk| fill(range, chunk)) };
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
    // memory is only written, through the raw pointer or through slices of memory
    // zeroed before they exist (`RowWriter::write`).
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

    /// Writes the rows `range` by `fill`, which receives their values zeroed: in place,
    /// or through this thread's scratch for large outputs (see the module).
    ///
    /// # Safety
    /// `range` lies within the rows, the array is alive, and no other thread writes these
    /// rows meanwhile (each chunk is written once, by one thread).
    pub unsafe fn write(&self, range: Range<usize>, fill: impl FnOnce(&mut [f64])) {
        assert!(range.start <= range.end && range.end <= self.rows, "rows of the array");
        let len = range.len() * self.row_len;
        // SAFETY: inside the array (asserted), and not written by anyone else (the
        // caller's promise).
        let target = unsafe { self.base.get().add(range.start * self.row_len) };
        let bytes = self.rows * self.row_len * std::mem::size_of::<f64>();
        if bytes >= STREAM_BYTES && len <= SCRATCH_VALUES {
            SCRATCH.with_borrow_mut(|scratch| {
                scratch.clear();
                scratch.resize(len, 0.0);
                fill(scratch);
                // SAFETY: `target` has room for `len` values (above).
                unsafe { stream_copy(scratch, target) };
            });
        } else {
            // SAFETY: as above; zeroed through the raw pointer before the slice exists.
            let chunk = unsafe {
                target.write_bytes(0, len);
                std::slice::from_raw_parts_mut(target, len)
            };
            fill(chunk);
        }
    }
}

/// Copies `values` to `target` with non-temporal (streaming) stores where the CPU has them
/// (SSE2, on every x86-64) and the target is 16-byte aligned (numpy aligns large arrays,
/// and a chunk starts a whole number of 16-byte pairs in), which write whole cache lines
/// without reading them first; a plain copy otherwise. The stores are fenced before
/// returning, so they are visible to whatever synchronises with this thread afterwards.
///
/// # Safety
/// `target` has room for `values.len()` values and does not overlap `values`.
unsafe fn stream_copy(values: &[f64], target: *mut f64) {
    #[cfg(target_arch = "x86_64")]
    if (target as usize) % 16 == 0 {
        use std::arch::x86_64::{_mm_loadu_pd, _mm_sfence, _mm_stream_pd};
        let pairs = values.len() / 2;
        // SAFETY: the caller's promise; each store writes two values at a 16-byte aligned
        // address inside the target.
        unsafe {
            for i in 0..pairs {
                _mm_stream_pd(target.add(2 * i), _mm_loadu_pd(values.as_ptr().add(2 * i)));
            }
            if values.len() % 2 == 1 {
                target.add(2 * pairs).write(values[2 * pairs]);
            }
            _mm_sfence();
        }
        return;
    }
    // SAFETY: the caller's promise.
    unsafe { std::ptr::copy_nonoverlapping(values.as_ptr(), target, values.len()) }
}
