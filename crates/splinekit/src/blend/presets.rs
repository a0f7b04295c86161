//! Ready-made animated blending splines: the seeds' beating heart and the plane, cylinder
//! and torus with moving patches. The same scenes exist as data in `examples/shapes/`.

use std::sync::Arc;

use super::animation::{Motion, Track};
use super::{BlendingCurveOptions, BlendingSplineCurve, BlendingSplineSurface, BlendingSurfaceOptions, LocalKind};
use crate::Point;
use crate::curve::model::Heart;
use crate::error::Result;
use crate::surface::model::{Cylinder, Plane, Torus};

/// A blending-spline surface with the animation tracks of its patches.
pub type AnimatedSurface = (BlendingSplineSurface<3>, Vec<Track<(usize, usize)>>);

fn oscillate(direction: [f64; 3], amplitude: f64) -> Motion {
    Motion::Oscillate { direction: direction.to_vec(), amplitude, frequency: 1.0, phase: 0.0 }
}
fn swing(amplitude: f64) -> Motion {
    Motion::Swing { axis: Some(vec![0.0, 0.0, 1.0]), amplitude, frequency: 1.0, phase: 0.0, pivot: None }
}

/// One track for each of the `count` patches (k, `row`) around a surface closed in u: patch
/// k at angle θ = 2πk/`count` moves radially, along (cos θ, sin θ, 0), by `amplitude` with
/// phase `phase(θ)`, one cycle a second.
fn radial_ring(count: usize, row: usize, amplitude: f64, phase: impl Fn(f64) -> f64) -> Vec<Track<(usize, usize)>> {
    (0..count)
        .map(|k| {
            let angle = std::f64::consts::TAU * k as f64 / count as f64;
            Track {
                local: (k, row),
                motions: vec![Motion::Oscillate {
                    direction: vec![angle.cos(), angle.sin(), 0.0],
                    amplitude,
                    frequency: 1.0,
                    phase: phase(angle),
                }],
            }
        })
        .collect()
}

/// The beating heart of the seed report: the closed heart (16 sin³t, 13 cos t − 5 cos 2t −
/// 2 cos 3t − cos 4t, 0) as 10 sub-curve locals blended by ERBS; locals 1–4 (right side) and
/// 6–9 (left side) move outwards and back along x, locals 0 (the dip) and 5 (the tip) along
/// y, and 1, 2, 8 and 9 also swing about z — one beat per second.
pub fn beating_heart() -> Result<(BlendingSplineCurve<3>, Vec<Track<usize>>)> {
    let curve = BlendingSplineCurve::from_model(
        Arc::new(Heart::new(1.0)?),
        10,
        &BlendingCurveOptions { local: LocalKind::SubCurve, closed: Some(true), ..Default::default() },
    )?;
    let mut tracks = Vec::new();
    for k in 1..=4 {
        tracks.push(Track { local: k, motions: vec![oscillate([1.0, 0.0, 0.0], 1.5)] });
    }
    for k in 6..=9 {
        tracks.push(Track { local: k, motions: vec![oscillate([-1.0, 0.0, 0.0], 1.5)] });
    }
    tracks.push(Track { local: 0, motions: vec![oscillate([0.0, -1.0, 0.0], 1.0)] });
    tracks.push(Track { local: 5, motions: vec![oscillate([0.0, -1.0, 0.0], 1.5)] });
    for (k, sign) in [(1, 1.0), (2, 1.0), (8, -1.0), (9, -1.0)] {
        tracks.iter_mut().find(|t| t.local == k).unwrap().motions.push(swing(0.2 * sign));
    }
    Ok((curve, tracks))
}

fn surface(
    model: Arc<dyn crate::surface::Surface<3>>,
    n: (usize, usize),
    closed: (bool, bool),
) -> Result<BlendingSplineSurface<3>> {
    BlendingSplineSurface::from_model(
        model,
        n,
        &BlendingSurfaceOptions { closed_u: Some(closed.0), closed_v: Some(closed.1), ..Default::default() },
    )
}

/// The unit plane \[0, 1\]² (z = 0) with 5×5 bicubic patches: the centre patch rises and falls
/// along z, two others swing about axes in the plane, one pulses.
pub fn animated_plane() -> Result<AnimatedSurface> {
    let plane = Plane::new(Point::<3>::zeros(), Point::<3>::new(1.0, 0.0, 0.0), Point::<3>::new(0.0, 1.0, 0.0))?;
    let s = surface(Arc::new(plane), (5, 5), (false, false))?;
    let tilt = |axis: [f64; 3], phase: f64| Motion::Swing {
        axis: Some(axis.to_vec()),
        amplitude: 0.6,
        frequency: 1.0,
        phase,
        pivot: None,
    };
    let tracks = vec![
        Track { local: (2, 2), motions: vec![oscillate([0.0, 0.0, 1.0], 0.3)] },
        Track { local: (1, 3), motions: vec![tilt([1.0, 0.0, 0.0], 0.0)] },
        Track { local: (3, 1), motions: vec![tilt([0.0, 1.0, 0.0], std::f64::consts::PI)] },
        Track {
            local: (3, 3),
            motions: vec![
                Motion::Pulse { amplitude: 0.5, frequency: 1.0, phase: 0.0 },
                oscillate([0.0, 0.0, 1.0], -0.15),
            ],
        },
    ];
    Ok((s, tracks))
}

/// The cylinder of radius 1 and height 2 with 8×4 bicubic patches (closed around): one
/// ring of patches breathes in and out radially with phases around the ring, one patch
/// rotates about the axis.
pub fn animated_cylinder() -> Result<AnimatedSurface> {
    let s = surface(Arc::new(Cylinder::new(1.0, 2.0)?), (8, 4), (true, false))?;
    let mut tracks = radial_ring(8, 2, 0.35, |angle| 2.0 * angle);
    tracks.push(Track {
        local: (2, 0),
        motions: vec![Motion::Swing {
            axis: Some(vec![0.0, 0.0, 1.0]),
            amplitude: 0.5,
            frequency: 1.0,
            phase: 0.0,
            pivot: Some(vec![0.0, 0.0, 0.0]),
        }],
    });
    Ok((s, tracks))
}

/// The torus R = 3, r = 1 with 8×6 bicubic patches (closed both ways): a wave of patches
/// on the outer equator moving outwards in turn, and a patch on top spinning about its
/// normal.
pub fn animated_torus() -> Result<AnimatedSurface> {
    let s = surface(Arc::new(Torus::new(3.0, 1.0)?), (8, 6), (true, true))?;
    let mut tracks = radial_ring(8, 0, 0.6, |angle| -angle);
    tracks.push(Track {
        local: (2, 1),
        motions: vec![Motion::Rotate {
            axis: Some(vec![0.0, 0.0, 1.0]),
            speed: std::f64::consts::TAU,
            phase: 0.0,
            pivot: None,
        }],
    });
    Ok((s, tracks))
}
