//! The constrained Delaunay triangulation of points in the plane (spade's
//! `ConstrainedDelaunayTriangulation`, incremental with a hierarchy for point location).
//!
//! Without constraint edges every triangle's circumcircle holds no other vertex in its
//! interior (the empty-circumcircle property; by Delaunay's lemma it is enough that every
//! edge is locally Delaunay, which Lawson flips restore after each insertion or removal).
//! A constraint edge is kept as an edge, and then the property holds for every triangle
//! with respect to the vertices it can *see* (not across a constraint).
//!
//! Vertices are numbered 0 … n − 1 in the order of [`Delaunay::vertices`]: the points as
//! given to [`Delaunay::new`], then as inserted. Inserting a point that is already a
//! vertex changes nothing, and [`Delaunay::remove`] renumbers: the last vertex takes the
//! removed one's number.

use spade::handles::FixedVertexHandle;
use spade::{ConstrainedDelaunayTriangulation, InsertionError, Point2, Triangulation};

use crate::Point;
use crate::error::{Error, Result};

/// A constrained Delaunay triangulation of points in the plane.
#[derive(Debug, Clone, Default)]
pub struct Delaunay {
    cdt: ConstrainedDelaunayTriangulation<Point2<f64>>,
}

fn insertion_error(field: String, p: &Point<2>, e: InsertionError) -> Error {
    let why = match e {
        InsertionError::NAN => "a coordinate is NaN".to_string(),
        InsertionError::TooLarge => format!("a coordinate exceeds {:e} in size", spade::MAX_ALLOWED_VALUE),
        InsertionError::TooSmall => {
            format!("a non-zero coordinate is smaller than {:e} in size", spade::MIN_ALLOWED_VALUE)
        }
    };
    Error::invalid(field, format!("cannot triangulate ({}, {}): {why}", p.x, p.y))
}

impl Delaunay {
    /// The Delaunay triangulation of `points` (bulk loaded, in O(n log n)); vertex i is
    /// `points[i]`.
    ///
    /// # Errors
    ///
    /// A coordinate that is NaN, infinite or outside spade's range (|x| ≤ 2¹⁰⁰, and 0 or
    /// |x| ≥ 2⁻¹⁴²), or a point given twice, naming `points[i]`.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::triangulation::Delaunay;
    /// // A unit square and its centre: four triangles around the centre.
    /// let p = |x: f64, y: f64| Point::<2>::new(x, y);
    /// let d = Delaunay::new(&[p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0), p(0.5, 0.5)]).unwrap();
    /// assert_eq!((d.num_vertices(), d.triangles().len()), (5, 4));
    /// assert!(Delaunay::new(&[p(f64::NAN, 0.0)]).is_err());
    /// ```
    pub fn new(points: &[Point<2>]) -> Result<Self> {
        for (i, p) in points.iter().enumerate() {
            if let Err(e) = spade::validate_vertex(&Point2::new(p.x, p.y)) {
                return Err(insertion_error(format!("points[{i}]"), p, e));
            }
        }
        let mut seen = std::collections::HashMap::with_capacity(points.len());
        for (i, p) in points.iter().enumerate() {
            // + 0.0 makes −0 and 0 the same key.
            if let Some(first) = seen.insert(((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits()), i) {
                return Err(Error::invalid(
                    format!("points[{i}]"),
                    format!("repeats points[{first}] = ({}, {})", p.x, p.y),
                ));
            }
        }
        // The CDT bulk loader keeps the input order (vertex i is points[i]).
        let cdt = ConstrainedDelaunayTriangulation::bulk_load_cdt(
            points.iter().map(|p| Point2::new(p.x, p.y)).collect(),
            Vec::new(),
        )
        .map_err(|e| Error::invalid("points", format!("cannot triangulate: {e}")))?;
        Ok(Delaunay { cdt })
    }

    /// [`Delaunay::new`] with the constraint edges `edges` (pairs of point numbers) added
    /// in order by [`Delaunay::add_constraint`]; an edge that cannot be added is an error
    /// naming `edges[k]`.
    pub fn with_constraints(points: &[Point<2>], edges: &[[usize; 2]]) -> Result<Self> {
        let mut d = Self::new(points)?;
        for (k, &[a, b]) in edges.iter().enumerate() {
            d.add_constraint(a, b).map_err(|e| match e {
                Error::Invalid { message, .. } => Error::invalid(format!("edges[{k}]"), message),
                other => other,
            })?;
        }
        Ok(d)
    }

    /// Inserts a point; returns its vertex number (an existing vertex's if it is one).
    pub fn insert(&mut self, p: Point<2>) -> Result<usize> {
        self.cdt.insert(Point2::new(p.x, p.y)).map(|h| h.index()).map_err(|e| insertion_error("point".into(), &p, e))
    }

    fn handle(&self, field: &str, i: usize) -> Result<FixedVertexHandle> {
        if i < self.cdt.num_vertices() {
            Ok(FixedVertexHandle::from_index(i))
        } else {
            Err(Error::invalid(field, format!("vertex {i} does not exist (there are {})", self.cdt.num_vertices())))
        }
    }

    /// Makes the segment between vertices `a` and `b` an edge of the triangulation (a
    /// constraint: flips never remove it). A vertex lying on the segment splits it.
    ///
    /// # Errors
    ///
    /// A vertex number out of range, `a` = `b`, or a segment crossing an existing
    /// constraint edge.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::triangulation::Delaunay;
    /// let p = |x: f64, y: f64| Point::<2>::new(x, y);
    /// // A thin rhombus: the Delaunay edge is the short diagonal 1–3; constrain the long one.
    /// let mut d = Delaunay::new(&[p(-2.0, 0.0), p(0.0, -0.5), p(2.0, 0.0), p(0.0, 0.5)]).unwrap();
    /// assert!(!d.triangles().iter().any(|t| t.contains(&0) && t.contains(&2)));
    /// d.add_constraint(0, 2).unwrap();
    /// assert!(d.triangles().iter().all(|t| t.contains(&0) && t.contains(&2)));
    /// assert!(d.add_constraint(1, 3).is_err()); // it would cross 0–2
    /// ```
    pub fn add_constraint(&mut self, a: usize, b: usize) -> Result<()> {
        let (ha, hb) = (self.handle("constraint", a)?, self.handle("constraint", b)?);
        if a == b {
            return Err(Error::invalid("constraint", format!("joins vertex {a} to itself")));
        }
        if !self.cdt.can_add_constraint(ha, hb) {
            return Err(Error::invalid(
                "constraint",
                format!("the segment {a}–{b} crosses an existing constraint edge"),
            ));
        }
        self.cdt.add_constraint(ha, hb);
        Ok(())
    }

    /// Removes vertex `i` and re-triangulates its hole (constraint edges at it go too);
    /// returns its position. The last vertex takes number `i`.
    pub fn remove(&mut self, i: usize) -> Result<Point<2>> {
        let h = self.handle("vertex", i)?;
        let p = self.cdt.remove(h);
        Ok(Point::<2>::new(p.x, p.y))
    }

    /// The number of vertices.
    pub fn num_vertices(&self) -> usize {
        self.cdt.num_vertices()
    }

    /// The vertices, by number.
    pub fn vertices(&self) -> Vec<Point<2>> {
        self.cdt.vertices().map(|v| Point::<2>::new(v.position().x, v.position().y)).collect()
    }

    /// The triangles as vertex numbers, each counter-clockwise.
    pub fn triangles(&self) -> Vec<[usize; 3]> {
        self.cdt.inner_faces().map(|f| f.vertices().map(|v| v.fix().index())).collect()
    }

    /// The constraint edges as pairs of vertex numbers.
    pub fn constraint_edges(&self) -> Vec<[usize; 2]> {
        self.cdt
            .undirected_edges()
            .filter(|e| self.cdt.is_constraint_edge(e.fix()))
            .map(|e| e.vertices().map(|v| v.fix().index()))
            .collect()
    }

    /// The edges as pairs of vertex numbers.
    pub fn edges(&self) -> Vec<[usize; 2]> {
        self.cdt.undirected_edges().map(|e| e.vertices().map(|v| v.fix().index())).collect()
    }

    /// The vertices on the convex hull, counter-clockwise.
    pub fn convex_hull(&self) -> Vec<usize> {
        let mut hull: Vec<usize> = self.cdt.convex_hull().map(|e| e.from().fix().index()).collect();
        // spade walks the hull clockwise (the outer face's boundary).
        hull.reverse();
        hull
    }

    pub(crate) fn spade(&self) -> &ConstrainedDelaunayTriangulation<Point2<f64>> {
        &self.cdt
    }
}
