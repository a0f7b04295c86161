//! Tessellation of curves meets its tolerance; SVG output is well-formed.

use splinekit::Point;
use splinekit::curve::model::{Butterfly, Circle};
use splinekit::curve::{BSplineCurve, Curve};
use splinekit_mesh::polyline::distance_to_segment;
use splinekit_mesh::{Polyline, Projection, SvgFigure};

/// Largest distance from densely sampled curve points to their polyline segment.
fn deviation<const D: usize>(c: &dyn Curve<D>, poly: &Polyline<D>) -> f64 {
    let n = poly.points.len();
    let segs = if poly.closed { n } else { n - 1 };
    let period = c.domain().length();
    (0..segs)
        .map(|i| {
            let (t0, mut t1) = (poly.params[i], if i + 1 < n { poly.params[i + 1] } else { poly.params[0] + period });
            if t1 < t0 {
                t1 += period;
            }
            let (a, b) = (poly.points[i], poly.points[(i + 1) % n]);
            (1..20).map(|k| distance_to_segment(&c.point(t0 + (t1 - t0) * k as f64 / 20.0), &a, &b)).fold(0.0, f64::max)
        })
        .fold(0.0, f64::max)
}

#[test]
fn adaptive_polylines_meet_the_tolerance() {
    let circle = Circle::new(1.0).unwrap();
    for tol in [1e-2, 1e-4, 1e-6] {
        let p = Polyline::adaptive(&circle, tol).unwrap();
        assert!(p.closed);
        let dev = deviation(&circle, &p);
        assert!(dev <= tol * 1.01, "tolerance {tol}: deviation {dev}");
        // Near-optimal: the chord height of a circle segment of angle θ is 1 − cos(θ/2).
        let optimal = (std::f64::consts::PI / (1.0 - tol).acos()).ceil() as usize;
        assert!(
            p.points.len() <= 2 * optimal + 16,
            "{} points for tolerance {tol} (optimal {optimal})",
            p.points.len()
        );
        assert!((p.length() - std::f64::consts::TAU).abs() < 10.0 * tol);
    }
    let b = Butterfly::new(1.0).unwrap();
    let p = Polyline::adaptive(&b, 1e-3).unwrap();
    assert!(deviation(&b, &p) <= 1e-3 * 1.01);
    let s = BSplineCurve::clamped_uniform(
        3,
        vec![
            Point::<2>::new(0.0, 0.0),
            Point::<2>::new(1.0, 3.0),
            Point::<2>::new(2.0, -3.0),
            Point::<2>::new(3.0, 0.0),
        ],
    )
    .unwrap();
    let p = Polyline::adaptive(&s, 1e-5).unwrap();
    assert!(!p.closed && p.params[0] == 0.0 && *p.params.last().unwrap() == 1.0);
    assert!(deviation(&s, &p) <= 1e-5 * 1.01);
}

#[test]
fn regular_polylines_and_bad_requests() {
    let circle = Circle::new(1.0).unwrap();
    let p = Polyline::regular(&circle, 8).unwrap();
    assert_eq!(p.points.len(), 8, "closed curves do not repeat the first point");
    assert!(Polyline::regular(&circle, 0).is_err());
    assert!(Polyline::regular(&circle, 1_000_000_000).is_err());
    assert!(Polyline::adaptive(&circle, 0.0).is_err());
    assert!(Polyline::adaptive(&circle, f64::NAN).is_err());
}

#[test]
fn svg_maps_points_into_the_picture() {
    let mut fig = SvgFigure::new(200.0, 100.0, Projection::TOP);
    fig.path(&[Point::<2>::new(0.0, 0.0), Point::<2>::new(4.0, 2.0)], false, "#000", 1.0);
    fig.dots(&[Point::<2>::new(2.0, 1.0)], 3.0, "red");
    let svg = fig.render().unwrap();
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    // Uniform scale: the 4×2 box is limited by the 60-pixel height inside 20-pixel margins
    // (30 px per unit), centred horizontally; y points up.
    assert!(svg.contains("M40.00,80.00 L160.00,20.00"), "{svg}");
    assert!(svg.contains(r#"cx="100.00" cy="50.00""#), "{svg}");
    // Points whose drawing coordinates are not finite are refused, naming the item.
    fig.dots(&[Point::<2>::new(f64::NAN, 1.0)], 3.0, "red");
    let e = fig.render().unwrap_err().to_string();
    assert!(e.starts_with("items[2] point 0"), "{e}");
    let mut far = SvgFigure::new(200.0, 100.0, Projection::TOP);
    far.path(&[Point::<2>::new(-1e308, 0.0), Point::<2>::new(1e308, 0.0)], false, "#000", 1.0);
    let e = far.render().unwrap_err().to_string();
    assert!(e.contains("not a finite number, which SVG needs"), "{e}");
}

#[test]
fn adaptive_polylines_estimate_their_size_before_flattening() {
    let circle = Circle::new(1.0).unwrap();
    let made = Polyline::adaptive(&circle, 1e-6).unwrap().points.len();
    // Within a small factor of what is made: 3× the points passes, a quarter is refused at
    // once by the estimate.
    assert!(Polyline::adaptive_with_limit(&circle, 1e-6, 3 * made).is_ok());
    let message = Polyline::adaptive_with_limit(&circle, 1e-6, made / 4).unwrap_err().to_string();
    assert!(message.starts_with("tolerance:") && message.contains("estimated"), "{message}");
    let message = Polyline::adaptive(&circle, 1e-300).unwrap_err().to_string();
    assert!(message.contains("1e-300") && message.contains("estimated"), "{message}");
}
