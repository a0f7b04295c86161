//! Default values of optional document fields (serde `default = "…"` functions).

pub(crate) fn is_false(b: &bool) -> bool {
    !*b
}
pub(crate) fn one() -> f64 {
    1.0
}
pub(crate) fn two() -> f64 {
    2.0
}
pub(crate) fn three() -> f64 {
    3.0
}
pub(crate) fn four() -> f64 {
    4.0
}
pub(crate) fn half() -> f64 {
    0.5
}
pub(crate) fn tenth() -> f64 {
    0.1
}
pub(crate) fn half_pi() -> f64 {
    std::f64::consts::FRAC_PI_2
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
pub(crate) fn y_axis() -> Vec<f64> {
    vec![0.0, 1.0, 0.0]
}
pub(crate) fn z_axis() -> Vec<f64> {
    vec![0.0, 0.0, 1.0]
}
