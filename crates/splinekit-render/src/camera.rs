//! Cameras: perspective (look-at, vertical field of view) or orthographic, and the matrices
//! wgpu wants (right-handed, depth in [0, 1]). Matrices are column-major `[[f32; 4]; 4]`.

/// A camera.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Camera {
    /// Perspective projection.
    Perspective {
        /// Eye position.
        eye: [f32; 3],
        /// Point looked at.
        target: [f32; 3],
        /// Up direction.
        up: [f32; 3],
        /// Vertical field of view in degrees.
        fov_y: f32,
    },
    /// Orthographic projection along `target − eye`, showing `half_height` above and below
    /// the view centre.
    Orthographic {
        /// Eye position.
        eye: [f32; 3],
        /// Point looked at (the view centre).
        target: [f32; 3],
        /// Up direction.
        up: [f32; 3],
        /// Half the visible height in world units.
        half_height: f32,
    },
}

type Mat4 = [[f32; 4]; 4];

fn sub(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn cross(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}
fn dot(a: [f32; 3], b: [f32; 3]) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn normalize(a: [f32; 3]) -> [f32; 3] {
    let n = dot(a, a).sqrt();
    if n > 0.0 { [a[0] / n, a[1] / n, a[2] / n] } else { [0.0, 0.0, 1.0] }
}

/// Column-major product a·b.
pub fn mul(a: &Mat4, b: &Mat4) -> Mat4 {
    let mut m = [[0.0; 4]; 4];
    for c in 0..4 {
        for r in 0..4 {
            m[c][r] = (0..4).map(|k| a[k][r] * b[c][k]).sum();
        }
    }
    m
}

fn look_at(eye: [f32; 3], target: [f32; 3], up: [f32; 3]) -> Mat4 {
    let f = normalize(sub(target, eye));
    let mut s = cross(f, up);
    if dot(s, s) < 1e-12 {
        // Looking along `up`: pick any side direction.
        s = cross(f, if f[0].abs() < 0.9 { [1.0, 0.0, 0.0] } else { [0.0, 1.0, 0.0] });
    }
    let s = normalize(s);
    let u = cross(s, f);
    [
        [s[0], u[0], -f[0], 0.0],
        [s[1], u[1], -f[1], 0.0],
        [s[2], u[2], -f[2], 0.0],
        [-dot(s, eye), -dot(u, eye), dot(f, eye), 1.0],
    ]
}

impl Camera {
    /// A perspective camera looking at the centre of the bounds from the direction given by
    /// `azimuth` (about z, from +x) and `elevation` (above the xy-plane), in radians, far
    /// enough for the bounding sphere to fit the view.
    pub fn fit(bounds: ([f32; 3], [f32; 3]), azimuth: f32, elevation: f32, aspect: f32) -> Camera {
        let (lo, hi) = bounds;
        let c = [(lo[0] + hi[0]) / 2.0, (lo[1] + hi[1]) / 2.0, (lo[2] + hi[2]) / 2.0];
        let r = (dot(sub(hi, lo), sub(hi, lo)).sqrt() / 2.0).max(1e-6);
        let fov_y: f32 = 30.0;
        // The half-angle of the narrower side of the view.
        let half = fov_y.to_radians() / 2.0;
        let fit_angle = if aspect < 1.0 { (half.tan() * aspect).atan() } else { half };
        let mut d = r / fit_angle.sin() * 1.02;
        let dir = [elevation.cos() * azimuth.cos(), elevation.cos() * azimuth.sin(), elevation.sin()];
        let at = |d: f32| Camera::Perspective {
            eye: [c[0] + d * dir[0], c[1] + d * dir[1], c[2] + d * dir[2]],
            target: c,
            up: [0.0, 0.0, 1.0],
            fov_y,
        };
        // The bounding sphere always fits; move closer until the box's corners fill about
        // 90 % of the view (the extent scales roughly as 1/distance).
        for _ in 0..6 {
            let m = at(d).view_projection(aspect, r);
            let mut extent: f32 = 0.0;
            for k in 0..8 {
                let p = [
                    if k & 1 == 0 { lo[0] } else { hi[0] },
                    if k & 2 == 0 { lo[1] } else { hi[1] },
                    if k & 4 == 0 { lo[2] } else { hi[2] },
                ];
                let w = (0..3).map(|j| m[j][3] * p[j]).sum::<f32>() + m[3][3];
                let x = ((0..3).map(|j| m[j][0] * p[j]).sum::<f32>() + m[3][0]) / w;
                let y = ((0..3).map(|j| m[j][1] * p[j]).sum::<f32>() + m[3][1]) / w;
                extent = extent.max(x.abs()).max(y.abs());
            }
            if !(extent > 0.0 && extent.is_finite()) {
                break;
            }
            d = (d * (0.35 + 0.65 * extent / 0.9)).max(r * 1.05);
        }
        at(d)
    }

    /// An orthographic camera looking down −z at the bounds (for plane figures), with a
    /// margin of 5 %.
    pub fn top(bounds: ([f32; 3], [f32; 3]), aspect: f32) -> Camera {
        let (lo, hi) = bounds;
        let c = [(lo[0] + hi[0]) / 2.0, (lo[1] + hi[1]) / 2.0, (lo[2] + hi[2]) / 2.0];
        let (w, h) = ((hi[0] - lo[0]).max(1e-6), (hi[1] - lo[1]).max(1e-6));
        let half_height = 0.55 * h.max(w / aspect);
        let depth = (hi[2] - lo[2]).max(w.max(h)) + 1.0;
        Camera::Orthographic { eye: [c[0], c[1], c[2] + depth], target: c, up: [0.0, 1.0, 0.0], half_height }
    }

    /// The same camera `factor` times as far from its target (perspective) or showing
    /// `factor` times as much (orthographic).
    pub fn zoomed(&self, factor: f32) -> Camera {
        match *self {
            Camera::Perspective { eye, target, up, fov_y } => Camera::Perspective {
                eye: [0, 1, 2].map(|k| target[k] + factor * (eye[k] - target[k])),
                target,
                up,
                fov_y,
            },
            Camera::Orthographic { eye, target, up, half_height } => {
                Camera::Orthographic { eye, target, up, half_height: half_height * factor }
            }
        }
    }

    /// The eye position.
    pub fn eye(&self) -> [f32; 3] {
        match *self {
            Camera::Perspective { eye, .. } | Camera::Orthographic { eye, .. } => eye,
        }
    }

    /// Projection × view, for a scene within `radius` of the target, at this aspect ratio.
    pub fn view_projection(&self, aspect: f32, radius: f32) -> Mat4 {
        match *self {
            Camera::Perspective { eye, target, up, fov_y } => {
                let dist = dot(sub(target, eye), sub(target, eye)).sqrt();
                let near = (dist - radius * 1.5).max(dist * 1e-3).max(1e-4);
                let far = dist + radius * 1.5 + 1.0;
                let f = 1.0 / (fov_y.to_radians() / 2.0).tan();
                // Right-handed, depth 0 at near and 1 at far.
                let proj = [
                    [f / aspect, 0.0, 0.0, 0.0],
                    [0.0, f, 0.0, 0.0],
                    [0.0, 0.0, far / (near - far), -1.0],
                    [0.0, 0.0, near * far / (near - far), 0.0],
                ];
                mul(&proj, &look_at(eye, target, up))
            }
            Camera::Orthographic { eye, target, up, half_height } => {
                let dist = dot(sub(target, eye), sub(target, eye)).sqrt();
                let (near, far) = (dist - radius * 1.5 - 1.0, dist + radius * 1.5 + 1.0);
                let (h, w) = (half_height, half_height * aspect);
                let proj = [
                    [1.0 / w, 0.0, 0.0, 0.0],
                    [0.0, 1.0 / h, 0.0, 0.0],
                    [0.0, 0.0, 1.0 / (near - far), 0.0],
                    [0.0, 0.0, near / (near - far), 1.0],
                ];
                mul(&proj, &look_at(eye, target, up))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn apply(m: &Mat4, p: [f32; 3]) -> [f32; 4] {
        let v = [p[0], p[1], p[2], 1.0];
        let mut o = [0.0; 4];
        for r in 0..4 {
            o[r] = (0..4).map(|c| m[c][r] * v[c]).sum();
        }
        o
    }

    #[test]
    fn the_target_projects_to_the_centre_inside_the_depth_range() {
        let cam = Camera::fit(([-1.0, -1.0, -1.0], [1.0, 1.0, 1.0]), 0.6, 0.4, 1.5);
        let m = cam.view_projection(1.5, 1.8);
        let c = apply(&m, [0.0, 0.0, 0.0]);
        assert!((c[0] / c[3]).abs() < 1e-5 && (c[1] / c[3]).abs() < 1e-5);
        let z = c[2] / c[3];
        assert!(z > 0.0 && z < 1.0);
        // Every corner of the box is in view.
        for k in 0..8 {
            let p = [
                if k & 1 == 0 { -1.0 } else { 1.0 },
                if k & 2 == 0 { -1.0 } else { 1.0 },
                if k & 4 == 0 { -1.0 } else { 1.0 },
            ];
            let q = apply(&m, p);
            assert!((q[0] / q[3]).abs() < 1.0 && (q[1] / q[3]).abs() < 1.0, "corner {p:?}");
        }
        let top = Camera::top(([0.0, 0.0, 0.0], [4.0, 1.0, 0.0]), 1.0);
        let m = top.view_projection(1.0, 3.0);
        let q = apply(&m, [4.0, 1.0, 0.0]);
        assert!(q[0] > 0.8 && q[0] < 1.0 && q[1] > 0.0);
    }
}
