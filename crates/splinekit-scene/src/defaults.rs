//! Default values of optional document fields that differ between documents (serde
//! `default = "…"` functions); documents whose fields all have defaults implement
//! `Default` instead.

pub(crate) fn is_false(b: &bool) -> bool {
    !*b
}
pub(crate) fn one() -> f64 {
    1.0
}
pub(crate) fn tau() -> f64 {
    std::f64::consts::TAU
}
pub(crate) fn origin() -> Vec<f64> {
    vec![0.0, 0.0, 0.0]
}
pub(crate) fn x_axis() -> Vec<f64> {
    vec![1.0, 0.0, 0.0]
}
pub(crate) fn z_axis() -> Vec<f64> {
    vec![0.0, 0.0, 1.0]
}
