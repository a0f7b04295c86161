//! Rigid motions of STEP geometry: a curve or surface carried into a placement (the frame
//! of an `AXIS2_PLACEMENT_3D`), parameters kept. Points map by p ↦ o + p₁x + p₂y + p₃z,
//! directions by d ↦ d₁x + d₂y + d₃z; placements compose (their origin is a point, their
//! axes directions), so every entity stays the same kind and keeps its parametrisation.

use splinekit::Point;
use splinekit::axes::OrthonormalAxes;

use crate::error::{Result, StepError};
use crate::geometry::{
    Axes, Curve, FaceEdge, FaceGeometry, FaceLoop, Geometry, LoopEdge, SplineCurve, SplineSurface, Surface,
};

/// The frame as a map of points and directions.
#[derive(Debug, Clone, Copy)]
pub struct Placement(pub Axes);

impl Placement {
    /// The frame of a document's `origin`, `axis` and `ref_direction` ([`OrthonormalAxes`]:
    /// z = axis/|axis|, x the part of `ref_direction` orthogonal to z, normalised; errors
    /// name the field).
    pub fn of_frame(origin: &[f64], axis: &[f64], ref_direction: &[f64]) -> Result<Placement> {
        let three = |field: &str, v: &[f64]| -> Result<[f64; 3]> {
            match v {
                [a, b, c] if v.iter().all(|x| x.is_finite()) => Ok([*a, *b, *c]),
                _ => Err(StepError::plain(format!("{field}: expected 3 finite coordinates, got {v:?}"))),
            }
        };
        let OrthonormalAxes { x, z, .. } =
            OrthonormalAxes::build(three("axis", axis)?, three("ref_direction", ref_direction)?)
                .map_err(|e| StepError::plain(e.to_string()))?;
        Ok(Placement(Axes { origin: three("origin", origin)?.into(), z: z.into(), x: x.into() }))
    }

    /// d₁x + d₂y + d₃z.
    pub fn direction(&self, d: Point<3>) -> Point<3> {
        let (x, y, z) = (self.0.x, self.0.y(), self.0.z);
        Point::<3>::from_fn(|k, _| d[0] * x[k] + d[1] * y[k] + d[2] * z[k])
    }

    /// o + p₁x + p₂y + p₃z.
    pub fn point(&self, p: Point<3>) -> Point<3> {
        self.0.origin + self.direction(p)
    }

    fn point_vec(&self, p: &[f64]) -> Vec<f64> {
        let p = Point::<3>::new(p[0], p.get(1).copied().unwrap_or(0.0), p.get(2).copied().unwrap_or(0.0));
        self.point(p).as_slice().to_vec()
    }

    fn axes(&self, a: &Axes) -> Axes {
        Axes { origin: self.point(a.origin), z: self.direction(a.z), x: self.direction(a.x) }
    }

    /// The curve moved into the placement.
    pub fn curve(&self, c: &Curve) -> Curve {
        match c {
            Curve::Line { origin, direction } => Curve::Line {
                origin: self.point_vec(origin),
                direction: self
                    .direction(Point::<3>::new(
                        direction[0],
                        direction.get(1).copied().unwrap_or(0.0),
                        direction.get(2).copied().unwrap_or(0.0),
                    ))
                    .as_slice()
                    .to_vec(),
            },
            Curve::Circle { axes, radius } => Curve::Circle { axes: self.axes(axes), radius: *radius },
            Curve::Ellipse { axes, a, b } => Curve::Ellipse { axes: self.axes(axes), a: *a, b: *b },
            Curve::Spline(s) => {
                Curve::Spline(SplineCurve { points: s.points.iter().map(|p| self.point_vec(p)).collect(), ..s.clone() })
            }
            Curve::Trimmed { basis, start, end } => {
                Curve::Trimmed { basis: Box::new(self.curve(basis)), start: *start, end: *end }
            }
        }
    }

    /// The surface moved into the placement.
    pub fn surface(&self, s: &Surface) -> Surface {
        match s {
            Surface::Plane(a) => Surface::Plane(self.axes(a)),
            Surface::Cylinder { axes, radius } => Surface::Cylinder { axes: self.axes(axes), radius: *radius },
            Surface::Cone { axes, radius, semi_angle } => {
                Surface::Cone { axes: self.axes(axes), radius: *radius, semi_angle: *semi_angle }
            }
            Surface::Sphere { axes, radius } => Surface::Sphere { axes: self.axes(axes), radius: *radius },
            Surface::Torus { axes, major_radius, minor_radius } => {
                Surface::Torus { axes: self.axes(axes), major_radius: *major_radius, minor_radius: *minor_radius }
            }
            Surface::Spline(b) => Surface::Spline(SplineSurface {
                points: b.points.iter().map(|row| row.iter().map(|p| self.point_vec(p)).collect()).collect(),
                ..b.clone()
            }),
            Surface::Revolution { profile, axis_origin, axis } => Surface::Revolution {
                profile: self.curve(profile),
                axis_origin: self.point(*axis_origin),
                axis: self.direction(*axis),
            },
            Surface::Extrusion { profile, direction } => {
                Surface::Extrusion { profile: self.curve(profile), direction: self.direction(*direction) }
            }
            Surface::Trimmed { basis, u, v } => Surface::Trimmed { basis: Box::new(self.surface(basis)), u: *u, v: *v },
        }
    }
}

impl Placement {
    /// The frame of a rigid motion (a scene object's placement, an assembly instance's):
    /// its translation and the images of x and z.
    pub fn of_transform(t: &splinekit_scene::placement::RigidTransform) -> Placement {
        let column = |j: usize| Point::<3>::new(t.rotation[0][j], t.rotation[1][j], t.rotation[2][j]);
        let [ox, oy, oz] = t.translation;
        Placement(Axes { origin: Point::<3>::new(ox, oy, oz), z: column(2), x: column(0) })
    }

    /// The face moved into the placement: its surface, vertices and 3-D edge curves (the
    /// pcurves, in the surface's own parameters, stay as they are).
    pub fn face(&self, f: &FaceGeometry) -> FaceGeometry {
        let loops = f
            .loops
            .iter()
            .map(|l| FaceLoop {
                edges: l
                    .edges
                    .iter()
                    .map(|e| match e {
                        LoopEdge::Edge(edge) => {
                            LoopEdge::Edge(Box::new(FaceEdge { curve: self.curve(&edge.curve), ..(**edge).clone() }))
                        }
                        LoopEdge::Again(k) => LoopEdge::Again(*k),
                    })
                    .collect(),
                ..l.clone()
            })
            .collect();
        FaceGeometry {
            surface: self.surface(&f.surface),
            vertices: f.vertices.iter().map(|p| self.point(*p)).collect(),
            loops,
        }
    }

    /// Any item's geometry moved into the placement.
    pub fn geometry(&self, g: &Geometry) -> Geometry {
        match g {
            Geometry::Curve(c) => Geometry::Curve(self.curve(c)),
            Geometry::Surface(s) => Geometry::Surface(self.surface(s)),
            Geometry::Face(f) => Geometry::Face(self.face(f)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn placements_compose_with_the_frames_they_move() {
        let v = Point::<3>::new;
        let p = Placement(Axes { origin: v(1.0, 2.0, 3.0), z: v(0.0, 1.0, 0.0), x: v(0.0, 0.0, 1.0) });
        // y = z × x = (1, 0, 0).
        assert_eq!(p.point(v(1.0, 2.0, 3.0)), v(1.0 + 2.0, 2.0 + 3.0, 3.0 + 1.0));
        let Surface::Sphere { axes, .. } = p.surface(&Surface::Sphere { axes: Axes::WORLD, radius: 1.0 }) else {
            unreachable!()
        };
        assert_eq!(axes, p.0);
    }
}
