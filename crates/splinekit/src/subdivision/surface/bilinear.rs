//! One bilinear step: the Catmull–Clark split (every n-gon into n quads) with vertices
//! kept, edge points at midpoints and face points at centroids. Its limit is the
//! bilinear patch of each quad (and of each child quad of an n-gon).

use super::cage::Cage;
use super::catmull_clark::{QuadRule, quad_split};
use super::topology::Topology;

/// One bilinear step (vertex order and faces as in [`super::catmull_clark::catmull_clark_step`]).
pub fn bilinear_step(cage: &Cage, topo: &Topology) -> Cage {
    quad_split(cage, topo, QuadRule::Bilinear)
}
