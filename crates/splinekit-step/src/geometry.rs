//! STEP geometry as plain data: the curves and surfaces of ISO 10303-42 that splinekit
//! writes and reads, with their parametrisations as the standard defines them. This is
//! the middle ground between Part 21 entities (`export`, `import`) and splinekit's
//! documents and kernel objects (`documents`).

use splinekit::Point;

/// `AXIS2_PLACEMENT_3D`: an origin with an orthonormal frame x (ref direction), y = z × x, z (axis).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Axes {
    /// Location.
    pub origin: Point<3>,
    /// Axis z (unit).
    pub z: Point<3>,
    /// Reference direction x (unit, orthogonal to z).
    pub x: Point<3>,
}

impl Axes {
    /// The standard frame at the origin.
    pub const WORLD: Axes = Axes {
        origin: Point::<3>::new(0.0, 0.0, 0.0),
        z: Point::<3>::new(0.0, 0.0, 1.0),
        x: Point::<3>::new(1.0, 0.0, 0.0),
    };

    /// y = z × x.
    pub fn y(&self) -> Point<3> {
        self.z.cross(&self.x)
    }

    /// origin + a·x + b·y + c·z.
    pub fn at(&self, a: f64, b: f64, c: f64) -> Point<3> {
        let y = self.y();
        Point::<3>::from_fn(|k, _| self.origin[k] + a * self.x[k] + b * y[k] + c * self.z[k])
    }
}

/// A B-spline or NURBS curve: c(t) = Σ N_{i,p}(t) w_i P_i / Σ N_{i,p}(t) w_i on
/// [t_p, t_n] over the full knot vector (n + p + 1 knots; STEP stores it as distinct values
/// with multiplicities). Points have 2 (parameter-space curves) or 3 coordinates.
#[derive(Debug, Clone, PartialEq)]
pub struct SplineCurve {
    /// Degree p.
    pub degree: usize,
    /// n + p + 1 knots.
    pub knots: Vec<f64>,
    /// n control points.
    pub points: Vec<Vec<f64>>,
    /// Weights (rational curves).
    pub weights: Option<Vec<f64>>,
    /// `closed_curve` flag: set for periodic curves, written as their n + p unrolled control
    /// points (the first p repeated at the end) over unclamped knots.
    pub closed: bool,
}

/// A B-spline or NURBS surface; the net's first index runs along u.
#[derive(Debug, Clone, PartialEq)]
pub struct SplineSurface {
    /// Degrees (p, q).
    pub degrees: (usize, usize),
    /// Knots in u.
    pub knots_u: Vec<f64>,
    /// Knots in v.
    pub knots_v: Vec<f64>,
    /// n_u rows of n_v points.
    pub points: Vec<Vec<Vec<f64>>>,
    /// Weights (rational surfaces), n_u rows of n_v.
    pub weights: Option<Vec<Vec<f64>>>,
    /// `u_closed`, `v_closed` flags.
    pub closed: (bool, bool),
}

/// A curve entity and its parametrisation (ISO 10303-42 §4.4).
#[derive(Debug, Clone, PartialEq)]
pub enum Curve {
    /// `LINE`: origin + t·direction (the direction carries the magnitude of its `VECTOR`).
    Line {
        /// A point on the line (2 or 3 coordinates).
        origin: Vec<f64>,
        /// The vector per unit parameter.
        direction: Vec<f64>,
    },
    /// `CIRCLE`: origin + r(cos t x + sin t y), t in radians.
    Circle {
        /// Centre and plane.
        axes: Axes,
        /// Radius.
        radius: f64,
    },
    /// `ELLIPSE`: origin + a cos t x + b sin t y.
    Ellipse {
        /// Centre and plane.
        axes: Axes,
        /// Semi-axis along x.
        a: f64,
        /// Semi-axis along y.
        b: f64,
    },
    /// `B_SPLINE_CURVE_WITH_KNOTS` (rational: the complex instance with
    /// `RATIONAL_B_SPLINE_CURVE`).
    Spline(SplineCurve),
    /// `TRIMMED_CURVE` of a basis curve between two parameter values, same sense.
    Trimmed {
        /// The basis curve.
        basis: Box<Curve>,
        /// Start parameter.
        start: f64,
        /// End parameter.
        end: f64,
    },
}

/// A surface entity and its parametrisation (ISO 10303-42 §4.4.7 ff.).
#[derive(Debug, Clone, PartialEq)]
pub enum Surface {
    /// `PLANE`: origin + u x + v y.
    Plane(Axes),
    /// `CYLINDRICAL_SURFACE`: origin + r(cos u x + sin u y) + v z.
    Cylinder {
        /// Placement.
        axes: Axes,
        /// Radius.
        radius: f64,
    },
    /// `CONICAL_SURFACE`: origin + (r + v tan α)(cos u x + sin u y) + v z, v the height
    /// (ISO 10303-42; pcurves and trims in the file use it). OpenCASCADE parametrises its
    /// cones along the generatrix, v_occ = v / cos α, and converts trims and pcurves
    /// when it reads and writes.
    Cone {
        /// Placement.
        axes: Axes,
        /// Radius at v = 0.
        radius: f64,
        /// Semi-angle α in radians, in (0, π/2) (OpenCASCADE raises smaller ones to 10⁻¹²).
        semi_angle: f64,
    },
    /// `SPHERICAL_SURFACE`: origin + r cos v (cos u x + sin u y) + r sin v z.
    Sphere {
        /// Placement.
        axes: Axes,
        /// Radius.
        radius: f64,
    },
    /// `TOROIDAL_SURFACE`: origin + (R + r cos v)(cos u x + sin u y) + r sin v z.
    Torus {
        /// Placement.
        axes: Axes,
        /// Major radius R.
        major_radius: f64,
        /// Minor radius r.
        minor_radius: f64,
    },
    /// `B_SPLINE_SURFACE_WITH_KNOTS` (rational: with `RATIONAL_B_SPLINE_SURFACE`).
    Spline(SplineSurface),
    /// `SURFACE_OF_REVOLUTION`: the profile point c(v) turned by the angle u about the axis.
    Revolution {
        /// The swept curve.
        profile: Curve,
        /// A point on the axis.
        axis_origin: Point<3>,
        /// The axis direction (unit).
        axis: Point<3>,
    },
    /// `SURFACE_OF_LINEAR_EXTRUSION`: c(u) + v·direction.
    Extrusion {
        /// The swept curve.
        profile: Curve,
        /// The extrusion vector (magnitude included).
        direction: Point<3>,
    },
    /// `RECTANGULAR_TRIMMED_SURFACE`: the basis on [u₀, u₁] × [v₀, v₁].
    Trimmed {
        /// The basis surface.
        basis: Box<Surface>,
        /// (u₀, u₁).
        u: (f64, f64),
        /// (v₀, v₁).
        v: (f64, f64),
    },
}

/// An edge of a face: a 3-D curve between two vertices and the same curve in the face
/// surface's (u, v) parameters (`PCURVE`), both over one parameter interval (the 3-D curve
/// runs from `start` to `end` as the parameter increases).
#[derive(Debug, Clone, PartialEq)]
pub struct FaceEdge {
    /// Index of the start vertex in [`FaceGeometry::vertices`].
    pub start: usize,
    /// Index of the end vertex (equal to `start` for a closed edge).
    pub end: usize,
    /// The 3-D curve.
    pub curve: Curve,
    /// The 2-D curve in the surface's parameter plane, same parameter as `curve`.
    pub pcurve: Curve,
    /// For a seam of a closed surface (`SEAM_CURVE`): the edge's other pcurve, on the far
    /// side of the periodic domain, same parameter; the loop uses the edge again reversed
    /// ([`LoopEdge::Again`]) along it.
    pub seam: Option<Curve>,
}

/// One use of an edge in a loop.
#[derive(Debug, Clone, PartialEq)]
pub enum LoopEdge {
    /// An edge used forwards (from its start to its end vertex).
    Edge(Box<FaceEdge>),
    /// The loop's edge at this index (a seam) used again, reversed, along its second pcurve.
    Again(usize),
}

/// One bound of a face: edges end to end forming a closed loop.
#[derive(Debug, Clone, PartialEq)]
pub struct FaceLoop {
    /// `FACE_OUTER_BOUND` (else `FACE_BOUND`, a hole).
    pub outer: bool,
    /// The bound's orientation flag: `true` when the edges as written already run with the
    /// face's material on their left in (u, v) (outer counter-clockwise, holes clockwise).
    pub orientation: bool,
    /// The edges in order.
    pub edges: Vec<LoopEdge>,
}

/// `ADVANCED_FACE`: a region of a surface bounded by loops of edges.
#[derive(Debug, Clone, PartialEq)]
pub struct FaceGeometry {
    /// The face's surface (an unbounded or B-spline surface, never rectangular trimmed).
    pub surface: Surface,
    /// Vertex points shared by the edges.
    pub vertices: Vec<Point<3>>,
    /// The bounds.
    pub loops: Vec<FaceLoop>,
}

/// A curve, a surface or a bounded face.
#[derive(Debug, Clone, PartialEq)]
pub enum Geometry {
    /// A curve.
    Curve(Curve),
    /// A surface.
    Surface(Surface),
    /// A face (written in a shell of a surface model).
    Face(FaceGeometry),
}

/// One named object of a STEP file.
#[derive(Debug, Clone, PartialEq)]
pub struct Item {
    /// The name (the entity's `name` attribute).
    pub name: String,
    /// Its geometry.
    pub geometry: Geometry,
}

/// Distinct knot values and their multiplicities, as STEP stores knots.
pub fn knot_multiplicities(knots: &[f64]) -> (Vec<f64>, Vec<usize>) {
    let mut values: Vec<f64> = Vec::new();
    let mut mults: Vec<usize> = Vec::new();
    for &k in knots {
        if values.last() == Some(&k) {
            *mults.last_mut().expect("same length") += 1;
        } else {
            values.push(k);
            mults.push(1);
        }
    }
    (values, mults)
}

/// The full knot vector of distinct values and multiplicities.
pub fn expand_knots(values: &[f64], mults: &[usize]) -> Vec<f64> {
    values.iter().zip(mults).flat_map(|(&k, &m)| std::iter::repeat_n(k, m)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn knots_compress_and_expand_exactly() {
        let k = vec![0.0, 0.0, 0.0, 0.25, 0.5, 0.5, 1.0, 1.0, 1.0];
        let (v, m) = knot_multiplicities(&k);
        assert_eq!(v, vec![0.0, 0.25, 0.5, 1.0]);
        assert_eq!(m, vec![3, 1, 2, 3]);
        assert_eq!(expand_knots(&v, &m), k);
    }

    #[test]
    fn axes_frame_is_right_handed() {
        assert_eq!(Axes::WORLD.y(), Point::<3>::new(0.0, 1.0, 0.0));
        assert_eq!(Axes::WORLD.at(1.0, 2.0, 3.0), Point::<3>::new(1.0, 2.0, 3.0));
    }
}
