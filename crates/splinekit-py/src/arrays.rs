//! numpy arrays in and out.
//!
//! Inputs may be numbers, lists, tuples or arrays of any real dtype and layout; they are
//! read as C-contiguous float64, which a C-contiguous float64 array already is (it is
//! then read in place, without a copy). Outputs are new C-contiguous float64 arrays that
//! the kernel writes into directly.

use std::mem::MaybeUninit;

use numpy::{PyArrayDyn, PyArrayMethods, PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyFloat, PyInt};
use splinekit::{Interval, Point};

use crate::errors::value_error;

/// `ob` as an aligned C-contiguous float64 array: itself when it already is one, else
/// `numpy.asarray(ob, dtype=float64, order="C")` (which keeps numbers 0-d), copied when
/// that is not aligned (arrays unpickled from out-of-band buffers or received over a
/// network, as Dask's are, may start at any byte).
pub fn contiguous<'py>(ob: &Bound<'py, PyAny>) -> PyResult<PyReadonlyArrayDyn<'py, f64>> {
    if let Ok(a) = ob.cast::<PyArrayDyn<f64>>()
        && a.is_c_contiguous()
        && a.is_aligned()
    {
        return Ok(a.readonly());
    }
    if let Some(x) = plain_number(ob) {
        let a = PyArrayDyn::<f64>::zeros(ob.py(), numpy::IxDyn(&[]), false);
        // SAFETY: a new 0-d array holding one f64, not yet shared with anyone.
        unsafe { *a.data() = x };
        return Ok(a.readonly());
    }
    let np = ob.py().import("numpy")?;
    let kwargs = pyo3::types::PyDict::new(ob.py());
    kwargs.set_item("dtype", np.getattr("float64")?)?;
    kwargs.set_item("order", "C")?;
    let converted = np.call_method("asarray", (ob,), Some(&kwargs))?.cast_into::<PyArrayDyn<f64>>()?;
    if converted.is_aligned() {
        return Ok(converted.readonly());
    }
    Ok(converted.call_method0("copy")?.cast_into::<PyArrayDyn<f64>>()?.readonly())
}

/// The value of a Python `float` (numpy's `float64` scalars are floats too) or `int`, which
/// `numpy.asarray(ob, dtype=float64)` would give (ints are rounded to the nearest double by
/// both); `None` for anything else, and for an int too large for a double (numpy's error
/// then). A scalar call (`c(0.5)`) so skips numpy's conversion: 0.55 µs against 1.4.
fn plain_number(ob: &Bound<'_, PyAny>) -> Option<f64> {
    if let Ok(f) = ob.cast::<PyFloat>() {
        return Some(f.value());
    }
    if ob.is_exact_instance_of::<PyInt>() {
        return ob.extract::<f64>().ok();
    }
    None
}

/// Numbers read from an argument: the values, the shape, and whether it was a scalar.
pub struct Numbers<'py> {
    array: PyReadonlyArrayDyn<'py, f64>,
}

impl<'py> Numbers<'py> {
    /// Reads `ob` (see [`contiguous`]).
    pub fn new(ob: &Bound<'py, PyAny>) -> PyResult<Self> {
        Ok(Numbers { array: contiguous(ob)? })
    }
    /// The values in C order.
    pub fn values(&self) -> &[f64] {
        self.array.as_slice().expect("contiguous")
    }
    /// The shape.
    pub fn shape(&self) -> Vec<usize> {
        self.array.shape().to_vec()
    }
    /// Whether the argument was a single number (0-d).
    pub fn is_scalar(&self) -> bool {
        self.array.ndim() == 0
    }
    /// The values of a scalar or 1-D argument named `field`; other shapes are an error.
    pub fn list(&self, field: &str) -> PyResult<&[f64]> {
        if self.array.ndim() > 1 {
            return Err(value_error(format!(
                "{field}: expected a number or a 1-D array, got an array of shape {:?}",
                self.shape()
            )));
        }
        Ok(self.values())
    }
    /// The coordinates of one point named `field` with `dimension` coordinates like the
    /// points of `shape` ("curve", "surface"); other shapes are an error.
    pub fn point(&self, field: &str, dimension: usize, shape: &str) -> PyResult<&[f64]> {
        let values = self.values();
        if self.array.ndim() != 1 || values.len() != dimension {
            return Err(value_error(format!(
                "{field}: expected {dimension} coordinates like the {shape}'s points, got {}",
                values.len()
            )));
        }
        Ok(values)
    }
    /// The rows of an (n, d) argument named `field` and d; other shapes are an error.
    pub fn rows(&self, field: &str) -> PyResult<(usize, usize)> {
        match self.shape()[..] {
            [n, d] if d > 0 => Ok((n, d)),
            _ => Err(value_error(format!(
                "{field}: expected an array of points of shape (n, d), got shape {:?}",
                self.shape()
            ))),
        }
    }
}

/// Checks that every value is finite, naming the first that is not as `field[i]`.
pub fn check_finite(field: &str, values: &[f64]) -> PyResult<()> {
    match values.iter().position(|v| !v.is_finite()) {
        Some(i) => Err(value_error(format!("{field}[{i}]: value is not finite ({})", values[i]))),
        None => Ok(()),
    }
}

/// The least and greatest value and whether all are finite, in one pass without an early
/// exit: AVX2 instructions where the CPU has them, else eight portable lanes.
fn bounds(values: &[f64]) -> (f64, f64, bool) {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU has AVX2 (checked just above).
        return unsafe { bounds_avx2(values) };
    }
    bounds_portable(values)
}

/// [`bounds_portable`] in AVX2 instructions: two vectors of four lanes each for the least
/// and the greatest value (`vminpd`, `vmaxpd`: `x < lo ? x : lo`, the portable lanes'
/// test) and the sum of `x · 0`; the rest after the blocks of eight by the portable code.
///
/// # Safety
/// The CPU must support AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn bounds_avx2(values: &[f64]) -> (f64, f64, bool) {
    use std::arch::x86_64::*;
    let chunks = values.chunks_exact(8);
    let rest = chunks.remainder();
    let (mut lo0, mut lo1) = (_mm256_set1_pd(f64::INFINITY), _mm256_set1_pd(f64::INFINITY));
    let (mut hi0, mut hi1) = (_mm256_set1_pd(f64::NEG_INFINITY), _mm256_set1_pd(f64::NEG_INFINITY));
    let (mut special0, mut special1) = (_mm256_setzero_pd(), _mm256_setzero_pd());
    for chunk in chunks {
        // SAFETY: eight values, read unaligned.
        let (x0, x1) = unsafe { (_mm256_loadu_pd(chunk.as_ptr()), _mm256_loadu_pd(chunk.as_ptr().add(4))) };
        (lo0, lo1) = (_mm256_min_pd(x0, lo0), _mm256_min_pd(x1, lo1));
        (hi0, hi1) = (_mm256_max_pd(x0, hi0), _mm256_max_pd(x1, hi1));
        special0 = _mm256_add_pd(special0, _mm256_mul_pd(x0, _mm256_setzero_pd()));
        special1 = _mm256_add_pd(special1, _mm256_mul_pd(x1, _mm256_setzero_pd()));
    }
    let lanes = |v0: __m256d, v1: __m256d| {
        let mut out = [0.0; 8];
        // SAFETY: eight values into an array of eight.
        unsafe { (_mm256_storeu_pd(out.as_mut_ptr(), v0), _mm256_storeu_pd(out.as_mut_ptr().add(4), v1)) };
        out
    };
    let (lo, hi, special) = (lanes(lo0, lo1), lanes(hi0, hi1), lanes(special0, special1));
    let (rest_lo, rest_hi, rest_finite) = bounds_portable(rest);
    (lo.into_iter().fold(rest_lo, f64::min), hi.into_iter().fold(rest_hi, f64::max), rest_finite && special == [0.0; 8])
}

/// [`bounds`] by eight lanes of `min`, `max` and `x · 0`, which is ±0 for a finite x and
/// NaN for ±∞ and NaN: their sum stays 0 exactly when every value is finite.
#[inline(always)]
fn bounds_portable(values: &[f64]) -> (f64, f64, bool) {
    const LANES: usize = 8;
    let (mut lo, mut hi, mut special) = ([f64::INFINITY; LANES], [f64::NEG_INFINITY; LANES], [0.0f64; LANES]);
    let chunks = values.chunks_exact(LANES);
    let rest = chunks.remainder();
    for chunk in chunks {
        let chunk: &[f64; LANES] = chunk.try_into().expect("LANES values");
        for i in 0..LANES {
            let x = chunk[i];
            lo[i] = if x < lo[i] { x } else { lo[i] };
            hi[i] = if x > hi[i] { x } else { hi[i] };
            special[i] += x * 0.0;
        }
    }
    for (i, &x) in rest.iter().enumerate() {
        lo[i] = if x < lo[i] { x } else { lo[i] };
        hi[i] = if x > hi[i] { x } else { hi[i] };
        special[i] += x * 0.0;
    }
    (
        lo.into_iter().fold(f64::INFINITY, f64::min),
        hi.into_iter().fold(f64::NEG_INFINITY, f64::max),
        special == [0.0; LANES],
    )
}

/// The slack of `splinekit eval --at` around a domain: 10⁻¹² of the largest of its length
/// and its ends' magnitudes.
fn slack(d: &Interval) -> f64 {
    1e-12 * d.length().max(d.start.abs()).max(d.end.abs())
}

/// Whether [`check_params`] accepts `params`: every value finite and, with a `domain`,
/// inside it (with the slack). One vectorised pass and no message: cheap enough to run
/// on each chunk of a batch just before the chunk is evaluated, while its parameters
/// are in cache (`Curve.__call__`).
pub fn params_pass(params: &[f64], domain: Option<Interval>) -> bool {
    let (lo, hi, finite) = bounds(params);
    finite && domain.is_none_or(|d| lo >= d.start - slack(&d) && hi <= d.end + slack(&d))
}

/// Refuses non-finite parameters and, with the `domain` of an open curve or direction (the
/// `open` thing of the message), parameters outside it (with the slack of
/// `splinekit eval --at`), naming `field`. One vectorised pass when all is well; the
/// offending value is looked for only when something is wrong.
pub fn check_params(field: &str, params: &[f64], domain: Option<Interval>, open: &str) -> PyResult<()> {
    if params_pass(params, domain) {
        return Ok(());
    }
    check_finite(field, params)?;
    let Some(d) = domain else { return Ok(()) };
    match params.iter().find(|&&t| t < d.start - slack(&d) || t > d.end + slack(&d)) {
        Some(t) => Err(value_error(format!(
            "{field}: parameter {t} is outside the domain [{}, {}] of this open {open}",
            d.start, d.end
        ))),
        None => Ok(()),
    }
}

/// Reads C-ordered coordinates (n × D numbers) as n points, in place.
pub fn as_points<const D: usize>(values: &[f64]) -> &[Point<D>] {
    const { assert!(std::mem::size_of::<Point<D>>() == D * std::mem::size_of::<f64>()) };
    assert_eq!(values.len() % D.max(1), 0, "whole points");
    // SAFETY: `Point<D>` is nalgebra's `#[repr(C)]` matrix over `#[repr(transparent)]`
    // `[[f64; D]; 1]` storage: D consecutive f64 with f64's alignment, as asserted above.
    unsafe { std::slice::from_raw_parts(values.as_ptr().cast::<Point<D>>(), values.len() / D.max(1)) }
}

/// Writes points into C-ordered coordinates (n × D numbers), in place.
pub fn as_points_mut<const D: usize>(values: &mut [f64]) -> &mut [Point<D>] {
    const { assert!(std::mem::size_of::<Point<D>>() == D * std::mem::size_of::<f64>()) };
    assert_eq!(values.len() % D.max(1), 0, "whole points");
    // SAFETY: as in `as_points`; the slice is borrowed mutably once.
    unsafe { std::slice::from_raw_parts_mut(values.as_mut_ptr().cast::<Point<D>>(), values.len() / D.max(1)) }
}

/// Writes points into C-ordered coordinates (n × D numbers) not yet written, in place.
pub fn as_points_uninit<const D: usize>(values: &mut [MaybeUninit<f64>]) -> &mut [MaybeUninit<Point<D>>] {
    const { assert!(std::mem::size_of::<Point<D>>() == D * std::mem::size_of::<f64>()) };
    assert_eq!(values.len() % D.max(1), 0, "whole points");
    // SAFETY: as in `as_points`; `MaybeUninit<T>` has `T`'s layout, and the slice is
    // borrowed mutably once.
    unsafe {
        std::slice::from_raw_parts_mut(values.as_mut_ptr().cast::<MaybeUninit<Point<D>>>(), values.len() / D.max(1))
    }
}

/// A new zero-filled C-contiguous float64 array of `shape`, which `fill` writes into with
/// the GIL released.
///
/// The array is allocated like `numpy.empty` (numpy backs large arrays with huge pages)
/// and zeroed here: writing 24 MB of freshly mapped zero pages (`numpy.zeros`) costs more
/// than evaluating a cubic B-spline into them (15 ms against 3 ms for 10⁶ × 3 values).
pub fn filled<'py>(
    py: Python<'py>,
    shape: &[usize],
    fill: impl FnOnce(&mut [f64]) + Send,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    // SAFETY: a new C-contiguous array of `len` f64 owned by us; every element is written
    // (zero) before any reference to the elements exists.
    let out = unsafe {
        let out = PyArrayDyn::<f64>::new(py, shape, false);
        out.data().write_bytes(0, out.len());
        out
    };
    {
        let mut rw = out.readwrite();
        let slice = rw.as_slice_mut().expect("a new array is contiguous");
        py.detach(|| fill(slice));
    }
    Ok(out)
}
