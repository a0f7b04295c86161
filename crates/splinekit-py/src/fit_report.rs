//! The report of a least-squares fit (`splinekit.FitReport`): its errors, the condition
//! estimate of the QR factor and the data parameters, with pickling. Made by
//! `fitting.rs`, carried along by the curve and surface classes.

use numpy::PyArray1;
use pyo3::prelude::*;

use crate::errors::value_error;

/// How well a least-squares fit matches its data, as ``splinekit fit --report`` prints:
/// ``rms_error`` = √(Σ|c(tᵢ) − Qᵢ|²/m), ``max_error`` = maxᵢ |c(tᵢ) − Qᵢ|, and
/// ``condition_estimate`` = max|R_kk|/min|R_kk| of the QR factor (a lower estimate of the
/// collocation matrix's condition number); ``params`` are the data parameters tᵢ.
#[pyclass(frozen, module = "splinekit", name = "FitReport")]
pub struct FitReport {
    /// √(Σ|c(tᵢ) − Qᵢ|²/m).
    #[pyo3(get)]
    pub(crate) rms_error: f64,
    /// maxᵢ |c(tᵢ) − Qᵢ|.
    #[pyo3(get)]
    pub(crate) max_error: f64,
    /// max|R_kk|/min|R_kk| of the QR factor.
    #[pyo3(get)]
    pub(crate) condition_estimate: f64,
    pub(crate) params: Vec<f64>,
}

#[pymethods]
impl FitReport {
    /// The data parameters tᵢ, shape (m,).
    #[getter]
    fn params<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.params)
    }
    fn __str__(&self) -> String {
        format!(
            "fit: rms error {:.6e}, max error {:.6e}, condition estimate {:.3e}",
            self.rms_error, self.max_error, self.condition_estimate
        )
    }
    fn __repr__(&self) -> String {
        format!("<FitReport {}>", self.__str__())
    }
    /// The pickle state: the three numbers and the parameters, the latter as the bytes of
    /// their little-endian doubles (exact, and one copy instead of a float object each).
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, pyo3::types::PyTuple>> {
        let restore = py.import("splinekit._splinekit")?.getattr("_restore")?;
        let bytes: Vec<u8> = self.params.iter().flat_map(|t| t.to_le_bytes()).collect();
        let params = pyo3::types::PyBytes::new(py, &bytes);
        let state = (self.rms_error, self.max_error, self.condition_estimate, params);
        ("fit_report", state, py.None()).into_pyobject(py).and_then(|args| (restore, args).into_pyobject(py))
    }
    /// The same errors, condition estimate and parameters.
    fn __eq__(&self, other: PyRef<'_, FitReport>) -> bool {
        (self.rms_error, self.max_error, self.condition_estimate)
            == (other.rms_error, other.max_error, other.condition_estimate)
            && self.params == other.params
    }
}

impl FitReport {
    /// The report of a `__reduce__` state `(rms_error, max_error, condition_estimate, params)`,
    /// `params` the bytes of little-endian doubles (or, as pickles of 0.1.0 before this
    /// change hold it, a list of floats).
    pub fn from_state(state: &Bound<'_, PyAny>) -> PyResult<Self> {
        let (rms_error, max_error, condition_estimate, raw): (f64, f64, f64, Bound<'_, PyAny>) = state.extract()?;
        let params = match raw.cast::<pyo3::types::PyBytes>() {
            Ok(bytes) => {
                let bytes = bytes.as_bytes();
                if bytes.len() % 8 != 0 {
                    return Err(value_error(format!(
                        "state: the parameters take {} bytes, not a whole number of doubles (8 bytes each)",
                        bytes.len()
                    )));
                }
                bytes.chunks_exact(8).map(|b| f64::from_le_bytes(b.try_into().expect("8 bytes"))).collect()
            }
            Err(_) => raw.extract()?,
        };
        Ok(FitReport { rms_error, max_error, condition_estimate, params })
    }
}
