//! The exact NURBS circle, refined and elevated without changing shape, with its
//! derivatives, curvature and length.
//!
//! cargo run -p splinekit --example nurbs_operations

use splinekit::Point;
use splinekit::curve::{CircleFrame, Curve, CurveArcLength, NurbsCurve};

fn main() -> splinekit::Result<()> {
    let circle = NurbsCurve::<3>::circle(&CircleFrame::in_xy_plane(Point::<3>::zeros(), 2.0))?;
    let refined = circle.refine(&[0.1, 0.3, 0.3])?.elevate_degree(2)?;
    println!(
        "degree {} → {}, control points {} → {}",
        circle.degree(),
        refined.degree(),
        circle.control_points().len(),
        refined.control_points().len()
    );
    let mut worst: f64 = 0.0;
    for i in 0..=1000 {
        let t = i as f64 / 1000.0;
        worst = worst.max((refined.point(t) - circle.point(t)).norm());
    }
    println!("largest distance between the two: {worst:.1e}");
    let mut d = [Point::<3>::zeros(); 3];
    circle.eval(0.125, &mut d);
    println!("c(1/8) = {:?}, c' = {:?}, curvature {:.15}", d[0].as_slice(), d[1].as_slice(), circle.curvature(0.125));
    println!("length {:.15} (2π·2 = {:.15})", circle.length(1e-13), 4.0 * std::f64::consts::PI);
    Ok(())
}
