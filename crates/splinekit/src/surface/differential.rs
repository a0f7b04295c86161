//! Differential geometry of a point of a surface from its partials: the unit normal, the
//! fundamental forms and the curvatures. A leaf module: the [`Surface`](super::Surface)
//! trait and the triangle family both read it.

use crate::Point;

/// First and second fundamental forms at a point of a surface in ℝ³.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FundamentalForms {
    /// E = S_u·S_u.
    pub e: f64,
    /// F = S_u·S_v.
    pub f: f64,
    /// G = S_v·S_v.
    pub g: f64,
    /// L = N·S_uu.
    pub l: f64,
    /// M = N·S_uv.
    pub m: f64,
    /// N = N·S_vv.
    pub n: f64,
}

/// Curvatures at a point of a surface in ℝ³.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Curvatures {
    /// Gaussian curvature K = (LN − M²)/(EG − F²).
    pub gaussian: f64,
    /// Mean curvature H = (EN − 2FM + GL) / (2(EG − F²)), with the sign of the normal
    /// S_u × S_v.
    pub mean: f64,
    /// Principal curvatures κ₁ = H + √(H² − K) ≥ κ₂ = H − √(H² − K).
    pub principal: (f64, f64),
}

impl FundamentalForms {
    /// The forms from the partials S_u, S_v, S_uu, S_uv, S_vv (ℝ³; `None` where
    /// S_u × S_v = 0).
    pub fn from_partials<const D: usize>(
        su: &Point<D>,
        sv: &Point<D>,
        suu: &Point<D>,
        suv: &Point<D>,
        svv: &Point<D>,
    ) -> Option<Self> {
        let n = unit_normal(su, sv)?;
        Some(FundamentalForms {
            e: su.dot(su),
            f: su.dot(sv),
            g: sv.dot(sv),
            l: n.dot(suu),
            m: n.dot(suv),
            n: n.dot(svv),
        })
    }
}

impl Curvatures {
    /// The curvatures given by the fundamental forms.
    pub fn of(ff: &FundamentalForms) -> Self {
        let det = ff.e * ff.g - ff.f * ff.f;
        let gaussian = (ff.l * ff.n - ff.m * ff.m) / det;
        let mean = (ff.e * ff.n - 2.0 * ff.f * ff.m + ff.g * ff.l) / (2.0 * det);
        let root = (mean * mean - gaussian).max(0.0).sqrt();
        Curvatures { gaussian, mean, principal: (mean + root, mean - root) }
    }
}

/// (a × b)/|a × b| for D = 3; `None` otherwise or when a × b = 0.
#[inline(always)]
pub fn unit_normal<const D: usize>(a: &Point<D>, b: &Point<D>) -> Option<Point<D>> {
    if D != 3 {
        return None;
    }
    let n = cross(a, b);
    // Test |n|² (not |n|) so the branch does not wait for the square root.
    let len2 = n.norm_squared();
    if len2 > f64::MIN_POSITIVE && len2.is_finite() {
        return Some(n * (1.0 / len2.sqrt()));
    }
    unit_normal_rescaled(a, b)
}

#[inline(always)]
fn cross<const D: usize>(a: &Point<D>, b: &Point<D>) -> Point<D> {
    let mut n = Point::<D>::zeros();
    n[0] = a[1] * b[2] - a[2] * b[1];
    n[1] = a[2] * b[0] - a[0] * b[2];
    n[2] = a[0] * b[1] - a[1] * b[0];
    n
}

/// The rare case where a × b under- or overflows: scale both partials to unit size first.
#[cold]
#[inline(never)]
fn unit_normal_rescaled<const D: usize>(a: &Point<D>, b: &Point<D>) -> Option<Point<D>> {
    let scale = |v: &Point<D>| {
        let m = v.iter().fold(0.0f64, |m, c| m.max(c.abs()));
        (m > 0.0 && m.is_finite()).then(|| v / m)
    };
    let n = cross(&scale(a)?, &scale(b)?);
    let len = n.norm();
    (len > 0.0 && len.is_finite()).then(|| n / len)
}
