//! The command line's resource budget applied to calls whose allocations grow with their
//! options (mesh densities, grids, orders of partials, samples per piece): the request is
//! estimated before any work starts and refused with the command line's one line naming
//! the argument, the estimate and the limit. The limits are the command line's defaults:
//! `SPLINEKIT_MAX_MEMORY` and `SPLINEKIT_MAX_WORK` when set (read at each call), else half
//! the physical memory and 10¹⁰ operations. Arrays the caller passed in are not counted:
//! their size is the caller's choice, already allocated.

use std::sync::OnceLock;

use pyo3::prelude::*;
use splinekit_scene::budget::{Budget, Cost, MEMORY_VARIABLE, ShapeCost, WORK_VARIABLE};

use crate::errors::OrValueError;

/// The budget of this call.
pub fn current() -> PyResult<Budget> {
    static MACHINE: OnceLock<Budget> = OnceLock::new();
    if std::env::var_os(MEMORY_VARIABLE).is_none() && std::env::var_os(WORK_VARIABLE).is_none() {
        return Ok(*MACHINE.get_or_init(Budget::machine));
    }
    Budget::from_options(None, None).or_value_error()
}

/// Refuses a request (building the shape of `shape` plus `request`) over the budget,
/// naming `field` and saying `what` it asks for.
pub fn check_request(field: &str, what: &str, shape: &ShapeCost, request: Cost) -> PyResult<()> {
    current()?.check(field, what, shape.build + request).or_value_error()
}
