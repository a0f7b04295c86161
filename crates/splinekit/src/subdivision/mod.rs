//! Subdivision curves (Chaikin, Lane–Riesenfeld of any degree, the 4-point scheme) and
//! subdivision surfaces ([`surface`]).

pub mod chaikin;
pub mod four_point;
pub mod lane_riesenfeld;
pub mod surface;

pub use chaikin::{ChaikinOptions, chaikin};
pub use four_point::{FourPointOptions, four_point};
pub use lane_riesenfeld::{lane_riesenfeld, lane_riesenfeld_limit};
