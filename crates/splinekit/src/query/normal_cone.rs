//! Cones that hold every normal direction of a surface cover patch.
//!
//! The s-partial of a patch's bicubic Hermite net lies in the convex cone of its twelve
//! s-legs 3(b_{i+1,j} − b_{i,j}), and the surface's own partial differs from it by at most
//! the patch's `slope_radius`; the same holds in t. If every S_s lies within angle a of a
//! unit axis e_s, every S_t within b of e_t, and the lines of e_s and e_t make the angle
//! γ > a + b, then the tangent plane's unit normal n = S_s × S_t / |S_s × S_t| makes with
//! n₀ = e_s × e_t / |e_s × e_t| an angle θ with
//! sin θ = max over unit w in the tangent plane of |w·n₀| ≤ (sin a + sin b) / sin(γ − a − b)
//! (w = αŝ + βt̂ has |α|, |β| ≤ 1 / sin(γ − a − b), and |ŝ·n₀| ≤ sin a, |t̂·n₀| ≤ sin b).

use crate::Point;
use crate::query::surface_cover::SurfacePatch;
use crate::query::tangent_cone::{TangentCone, angle};
use std::f64::consts::{FRAC_PI_2, PI};

/// The undirected cone of the unit normals of `patch` (half-angle π when the bound above
/// says nothing).
pub fn normal_cone(patch: &SurfacePatch<3>) -> TangentCone<3> {
    let b = &patch.control;
    let mut legs_s = [Point::<3>::zeros(); 12];
    let mut legs_t = [Point::<3>::zeros(); 12];
    for i in 0..3 {
        for j in 0..4 {
            legs_s[i * 4 + j] = (b[(i + 1) * 4 + j] - b[i * 4 + j]) * 3.0;
            legs_t[i * 4 + j] = (b[j * 4 + i + 1] - b[j * 4 + i]) * 3.0;
        }
    }
    let cs = TangentCone::of_legs(&legs_s, patch.slope_radius);
    let ct = TangentCone::of_legs(&legs_t, patch.slope_radius);
    let all = TangentCone { axis: Point::<3>::zeros(), half_angle: PI };
    if cs.half_angle >= FRAC_PI_2 || ct.half_angle >= FRAC_PI_2 {
        return all;
    }
    let between = angle(&cs.axis, &ct.axis);
    let gap = between.min(PI - between) - cs.half_angle - ct.half_angle;
    let axis = cs.axis.cross(&ct.axis);
    if gap <= 0.0 || axis.norm() == 0.0 {
        return all;
    }
    let sine = (cs.half_angle.sin() + ct.half_angle.sin()) / gap.sin();
    if sine >= 1.0 {
        return all;
    }
    TangentCone { axis: axis.normalize(), half_angle: sine.asin() }
}

/// Whether a curve piece with tangent cone `tangents` meets a patch with normal cone
/// `normals` at most once: when every tangent makes an angle below 90° − (normal
/// half-angle) with the normal axis, the curve's height over the patch (a graph over the
/// plane normal to the axis, one-to-one because the partial cones are apart) changes
/// monotonically along the piece.
pub fn transversal(tangents: &TangentCone<3>, normals: &TangentCone<3>) -> bool {
    if tangents.half_angle >= FRAC_PI_2 || normals.half_angle >= FRAC_PI_2 {
        return false;
    }
    let between = angle(&tangents.axis, &normals.axis);
    between.min(PI - between) + tangents.half_angle + normals.half_angle < FRAC_PI_2
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Interval;
    use crate::surface::Surface;
    use crate::surface::model::Sphere;

    #[test]
    fn sphere_normals_lie_in_their_patch_cones() {
        let sphere = Sphere::new(2.0).unwrap();
        let patch = SurfacePatch::new(&sphere, Interval::new(0.3, 0.5), Interval::new(-0.2, 0.1));
        let cone = normal_cone(&patch);
        assert!(cone.half_angle < 0.5, "half-angle {}", cone.half_angle);
        for k in 0..=20 {
            let (u, v) = (patch.u().lerp(k as f64 / 20.0), patch.v().lerp((k * 7 % 21) as f64 / 20.0));
            let n = sphere.normal(u, v).unwrap();
            let a = angle(&cone.axis, &n);
            assert!(a.min(PI - a) <= cone.half_angle, "normal at ({u}, {v}) outside the cone");
        }
    }
}
