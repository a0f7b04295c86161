//! `bicubic_hermite` documents: the bicubic patch of corner data (positions, first
//! partials, twists), written exactly as a Bézier surface.

use std::borrow::Cow;

use serde::{Deserialize, Serialize};
use splinekit::Point;
use splinekit::surface::{BezierSurface, HermiteCorner, Surface};

use super::{SurfaceDecoration, SurfaceForm, Surfaces};
use crate::budget::ShapeCost;
use crate::error::{DocumentError, Result};
use crate::points::{from_points, to_point};
use crate::registry::DocumentKind;
use crate::views::NetView;

/// `{"type":"bicubic_hermite","hermite":[[C00, C01], [C10, C11]]}` with C_ab =
/// [[S, S_v], [S_u, S_uv]] at the corner (u, v) = (a, b) of [0, 1]² (the layout of a
/// blending-spline surface's `hermite` entries: `hermite[a][b][i][j]` = ∂^{i+j}S/∂uⁱ∂vʲ).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BicubicHermiteDoc {
    /// `hermite[a][b][i][j]`: 2 × 2 corners of 2 × 2 partials, points of one dimension.
    pub hermite: Vec<Vec<Vec<Vec<Vec<f64>>>>>,
}

impl BicubicHermiteDoc {
    /// The checked corner data in dimension D.
    fn corners<const D: usize>(&self) -> Result<[[HermiteCorner<D>; 2]; 2]> {
        let count =
            |field: &str, what: &str, got: usize| DocumentError::new(field, format!("expected 2 {what}, got {got}"));
        if self.hermite.len() != 2 {
            return Err(count("hermite", "rows of corners (u = 0 and u = 1)", self.hermite.len()));
        }
        let mut out = [[HermiteCorner {
            point: Point::<D>::zeros(),
            du: Point::<D>::zeros(),
            dv: Point::<D>::zeros(),
            duv: Point::<D>::zeros(),
        }; 2]; 2];
        for (a, row) in self.hermite.iter().enumerate() {
            if row.len() != 2 {
                return Err(count(&format!("hermite[{a}]"), "corners (v = 0 and v = 1)", row.len()));
            }
            for (b, corner) in row.iter().enumerate() {
                let field = format!("hermite[{a}][{b}]");
                if corner.len() != 2 {
                    return Err(count(&field, "rows of partials ([S, S_v] and [S_u, S_uv])", corner.len()));
                }
                for (i, partials) in corner.iter().enumerate() {
                    if partials.len() != 2 {
                        return Err(count(&format!("{field}[{i}]"), "partials", partials.len()));
                    }
                }
                let p = |i: usize, j: usize| to_point::<D>(&format!("{field}[{i}][{j}]"), &corner[i][j]);
                out[a][b] = HermiteCorner { point: p(0, 0)?, dv: p(0, 1)?, du: p(1, 0)?, duv: p(1, 1)? };
            }
        }
        Ok(out)
    }

    /// The dimension: that of the first position.
    fn first_dimension(&self) -> Result<usize> {
        let first = self
            .hermite
            .first()
            .and_then(|r| r.first())
            .and_then(|c| c.first())
            .and_then(|p| p.first())
            .ok_or_else(|| DocumentError::new("hermite", "expected 2 × 2 corners of [[S, S_v], [S_u, S_uv]]"))?;
        match first.len() {
            0 => Err(DocumentError::new("hermite[0][0][0][0]", "a point needs at least 1 coordinate, got 0")),
            d => Ok(d),
        }
    }

    /// The Bézier net, rows along u, as plain arrays.
    fn net(&self) -> Result<Vec<Vec<Vec<f64>>>> {
        crate::with_dimension!(self.first_dimension()?, "hermite", D => {
            let s = BezierSurface::bicubic_hermite(self.corners::<D>()?).map_err(DocumentError::from)?;
            Ok(s.control_points().iter().map(|row| from_points(row)).collect())
        })
    }
}

impl DocumentKind for BicubicHermiteDoc {
    type Family = Surfaces;
    fn dimension(&self) -> Result<usize> {
        let d = self.first_dimension()?;
        crate::with_dimension!(d, "hermite", D => self.corners::<D>().map(|_| d))
    }
    /// A bicubic Bézier patch.
    fn cost(&self) -> ShapeCost {
        ShapeCost::new("hermite", 16.0 * 4.0 * 8.0, 64.0, 80.0 * 4.0)
    }
    fn build_in<const D: usize>(&self) -> Result<Box<dyn Surface<D>>> {
        Ok(Box::new(BezierSurface::bicubic_hermite(self.corners::<D>()?).map_err(DocumentError::from)?))
    }
    /// A saddle-like patch with tilted corners and twists.
    fn example() -> Self {
        let corner = |u: f64, v: f64| {
            vec![
                vec![vec![u, v, 0.5 * u * v], vec![0.0, 1.0, 0.5 * u + 0.6]],
                vec![vec![1.0, 0.0, 0.5 * v - 0.6], vec![0.0, 0.0, 1.5]],
            ]
        };
        BicubicHermiteDoc {
            hermite: vec![vec![corner(0.0, 0.0), corner(0.0, 1.0)], vec![corner(1.0, 0.0), corner(1.0, 1.0)]],
        }
    }
    fn decoration(&self) -> SurfaceDecoration<'_> {
        SurfaceDecoration::None
    }
    fn set_time(&mut self, _time: f64) {}
    /// No control net of its own: the net is made from the data, which is what edits
    /// change.
    fn spline(&self) -> Option<NetView<'_>> {
        None
    }
    /// The bicubic Bézier net made from the data.
    fn exact_form(&self) -> Result<SurfaceForm<'_>> {
        Ok(SurfaceForm::Spline(NetView {
            degrees: (3, 3),
            control_points: Cow::Owned(self.net()?),
            knots: None,
            weights: None,
            periodic: (false, false),
        }))
    }
    const BLENDING_MODEL: bool = false;
}
