//! Fit closed cubic B-splines to a sampled circle and watch the error fall as the number
//! of control points grows (the seeds' least-squares exercise).
//!
//! cargo run -p splinekit --example fit_circle

use splinekit::curve::Curve;
use splinekit::curve::model::Circle;
use splinekit::fit::{FitOptions, KnotPlacement, fit_curve};

fn main() -> splinekit::Result<()> {
    let circle = Circle::new(1.0)?;
    println!("control points   max radius error   condition estimate");
    for n in [6, 8, 12, 16, 24, 32] {
        let mut options = FitOptions::new(3, n);
        options.closed = true;
        options.knots = KnotPlacement::Uniform;
        let fit = fit_curve(&circle, 500, &options)?;
        let err = (0..2000).map(|i| (fit.curve.point(i as f64 / 2000.0).norm() - 1.0).abs()).fold(0.0, f64::max);
        println!("{n:>14}   {err:>16.3e}   {:>18.3}", fit.condition_estimate);
    }
    Ok(())
}
