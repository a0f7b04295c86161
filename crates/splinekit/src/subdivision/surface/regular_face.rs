//! The limit on a regular face as a polynomial patch, in the face's own parameters: the
//! bicubic B-spline patch of the 4 × 4 grid around a regular Catmull–Clark quad
//! ([`super::regular_patch::catmull_clark_grid`], [`super::regular_patch::cubic_bspline_basis`])
//! or the quartic box spline of the 12 points around a regular Loop triangle, phantom
//! points beyond a crease or boundary included
//! ([`super::regular_patch::loop_control_points`], [`super::box_spline::loop_basis`]).
//! Local subdivision ([`super::limit_eval`]) ends here as soon as its face is regular.

use super::box_spline::loop_basis;
use super::cage::Cage;
use super::limit_eval::EvalScheme;
use super::regular_patch::{catmull_clark_grid, cubic_bspline_basis, loop_control_points};
use super::topology::Topology;
use crate::Point;

/// Position and partials [P, Pu, Pv, Puu, Puv, Pvv] on a regular face, or None.
pub(crate) fn regular(
    cage: &Cage,
    topo: &Topology,
    f: u32,
    scheme: EvalScheme,
    u: f64,
    v: f64,
) -> Option<[Point<3>; 6]> {
    let mut r = [Point::<3>::zeros(); 6];
    match scheme {
        EvalScheme::CatmullClark => {
            let g = catmull_clark_grid(cage, topo, f)?;
            let (bu, bv) = (cubic_bspline_basis(u), cubic_bspline_basis(v));
            let orders = [(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2)];
            for (d, &(du, dv)) in orders.iter().enumerate() {
                for i in 0..4 {
                    for j in 0..4 {
                        r[d] += g[i][j] * (bu[du][i] * bv[dv][j]);
                    }
                }
            }
        }
        EvalScheme::Loop => {
            let pts = loop_control_points(cage, topo, f)?;
            let w = loop_basis(u, v);
            for (d, row) in w.iter().enumerate() {
                for (k, &p) in pts.iter().enumerate() {
                    r[d] += p * row[k];
                }
            }
        }
    }
    Some(r)
}
