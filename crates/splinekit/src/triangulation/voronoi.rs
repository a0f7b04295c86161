//! The Voronoi diagram, the dual of the Delaunay triangulation: the cell of a site is the
//! set of points nearer to it than to any other site, a convex polygon whose vertices are
//! the circumcentres of the Delaunay triangles around the site (each equidistant from its
//! three sites). Cells of sites on the convex hull are unbounded. With constraint edges
//! the same construction gives the dual of the constrained triangulation, which is not a
//! nearest-site diagram across the constraints.

use spade::Triangulation;

use crate::Point;
use crate::triangulation::Delaunay;

/// The Voronoi cell of one site.
#[derive(Debug, Clone, PartialEq)]
pub struct VoronoiCell {
    /// The site (a vertex of the triangulation).
    pub site: Point<2>,
    /// The cell's vertices, the circumcentres of the triangles around the site,
    /// counter-clockwise; for an unbounded cell the finite chain between its two rays.
    pub vertices: Vec<Point<2>>,
    /// Whether the cell is a bounded polygon (the site is not on the convex hull).
    pub bounded: bool,
}

impl Delaunay {
    /// The circumcentres of the triangles, in the order of [`Delaunay::triangles`]: the
    /// vertices of the Voronoi diagram.
    pub fn circumcenters(&self) -> Vec<Point<2>> {
        self.spade()
            .inner_faces()
            .map(|f| {
                let c = f.circumcenter();
                Point::<2>::new(c.x, c.y)
            })
            .collect()
    }

    /// The Voronoi cell of every vertex, by vertex number.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::triangulation::Delaunay;
    /// // The centre of a square is the only bounded cell: the square of the circumcentres
    /// // (½, 0), (1, ½), (½, 1), (0, ½).
    /// let p = |x: f64, y: f64| Point::<2>::new(x, y);
    /// let d = Delaunay::new(&[p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0), p(0.5, 0.5)]).unwrap();
    /// let cells = d.voronoi_cells();
    /// assert_eq!(cells.iter().filter(|c| c.bounded).count(), 1);
    /// assert_eq!(cells[4].vertices.len(), 4);
    /// assert!(cells[4].vertices.iter().all(|v| ((v - p(0.5, 0.5)).norm() - 0.5).abs() < 1e-15));
    /// ```
    pub fn voronoi_cells(&self) -> Vec<VoronoiCell> {
        let t = self.spade();
        t.vertices()
            .map(|v| {
                let site = Point::<2>::new(v.position().x, v.position().y);
                // Faces left of the out-edges, in spade's order around the vertex.
                let faces: Vec<Option<Point<2>>> = v
                    .out_edges()
                    .map(|e| {
                        e.face().as_inner().map(|f| {
                            let c = f.circumcenter();
                            Point::<2>::new(c.x, c.y)
                        })
                    })
                    .collect();
                let bounded = faces.iter().all(Option::is_some);
                // Start after the outer face for unbounded cells, so the chain is unbroken.
                let start = faces.iter().position(Option::is_none).map_or(0, |i| i + 1);
                let mut vertices: Vec<Point<2>> =
                    (0..faces.len()).filter_map(|k| faces[(start + k) % faces.len()]).collect();
                // Orient counter-clockwise about the site.
                let turn: f64 = vertices
                    .windows(2)
                    .map(|w| {
                        let (a, b) = (w[0] - site, w[1] - site);
                        a.x * b.y - a.y * b.x
                    })
                    .sum();
                if turn < 0.0 {
                    vertices.reverse();
                }
                VoronoiCell { site, vertices, bounded }
            })
            .collect()
    }
}
