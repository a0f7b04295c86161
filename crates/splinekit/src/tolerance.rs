//! The kernel's shared tolerances, each named for what it compares. Tolerances used by one
//! algorithm only are named constants beside it.

/// Parameters, knots and angles computed by arithmetic that should reproduce a given value
/// (a periodic knot vector repeating its spacing, uniform knots, a full turn, one period
/// cut from an unrolled spline): equal when they differ by at most this fraction of the
/// size of the values compared.
pub const PARAMETER_RELATIVE: f64 = 1e-12;

/// Slack in radians for a sweep computed as end − start: a full turn may exceed 2π by
/// this much, and a sweep of k quarter turns is split into k segments, not k + 1.
pub const ANGLE_SLACK: f64 = 1e-12;

/// Curve ends that must meet (the corners of a Coons patch, a trimming loop closing): they
/// meet when their distance is at most this fraction of max(1, |end points|).
pub const JOIN_RELATIVE: f64 = 1e-9;
