//! The camera of the 3-D view and the mouse: orbit (turntable about world z and the view's
//! side axis), pan in the view plane, zoom, standard views, framing; and the projection of
//! world points to view pixels and back (the renderer's own view–projection matrix, so what
//! is picked is what is drawn).

use nalgebra::{Matrix4, Rotation3, Unit, Vector3, Vector4};
use splinekit_render::{Camera, RenderScene};
use splinekit_scene::scenes::CameraDoc;

/// A standard direction to look from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StandardView {
    /// From +z, y up.
    Top,
    /// From −y, z up.
    Front,
    /// From +x, z up.
    Side,
}

/// The 3-D view's camera and the one it started from (Home).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ViewCamera {
    /// The camera drawn with.
    pub camera: Camera,
    /// The camera Home returns to.
    pub home: Camera,
}

fn v3(a: [f32; 3]) -> Vector3<f32> {
    Vector3::new(a[0], a[1], a[2])
}

fn parts(c: &Camera) -> (Vector3<f32>, Vector3<f32>, Vector3<f32>) {
    match *c {
        Camera::Perspective { eye, target, up, .. } | Camera::Orthographic { eye, target, up, .. } => {
            (v3(eye), v3(target), v3(up))
        }
    }
}

fn with_parts(c: &Camera, eye: Vector3<f32>, target: Vector3<f32>, up: Vector3<f32>) -> Camera {
    let (eye, target, up) = (eye.into(), target.into(), up.into());
    match *c {
        Camera::Perspective { fov_y, .. } => Camera::Perspective { eye, target, up, fov_y },
        Camera::Orthographic { half_height, .. } => Camera::Orthographic { eye, target, up, half_height },
    }
}

impl ViewCamera {
    /// Starts at `camera`.
    pub fn new(camera: Camera) -> Self {
        ViewCamera { camera, home: camera }
    }

    /// Turns the eye about the target: `dx` radians about world z, `dy` about the view's
    /// side axis (kept short of the poles).
    pub fn orbit(&mut self, dx: f32, dy: f32) {
        let (eye, target, up) = parts(&self.camera);
        let offset = eye - target;
        let about_z = Rotation3::from_axis_angle(&Vector3::z_axis(), -dx);
        let side = offset.cross(&up);
        let tilt = if side.norm() > 1e-9 {
            Rotation3::from_axis_angle(&Unit::new_normalize(side), dy)
        } else {
            Rotation3::identity()
        };
        let turned = about_z * tilt * offset;
        let new_up = about_z * tilt * up;
        // Stay off the pole unless the view already looks along z (top view).
        let along_z = turned.normalize().z.abs();
        if along_z > 0.999 && up.z.abs() > 0.5 {
            self.camera = with_parts(&self.camera, target + about_z * offset, target, about_z * up);
            return;
        }
        self.camera = with_parts(&self.camera, target + turned, target, new_up);
    }

    /// Moves eye and target by (dx, dy) pixels of a view `height` pixels high.
    pub fn pan(&mut self, dx: f32, dy: f32, height: f32) {
        let (eye, target, up) = parts(&self.camera);
        let forward = (target - eye).normalize();
        let right = forward.cross(&up).normalize();
        let true_up = right.cross(&forward);
        let world_per_pixel = 2.0 * self.half_height() / height.max(1.0);
        let shift = (-dx * right + dy * true_up) * world_per_pixel;
        self.camera = with_parts(&self.camera, eye + shift, target + shift, up);
    }

    /// Half the visible height at the target in world units.
    fn half_height(&self) -> f32 {
        match self.camera {
            Camera::Orthographic { half_height, .. } => half_height,
            Camera::Perspective { eye, target, fov_y, .. } => {
                (v3(eye) - v3(target)).norm() * (fov_y.to_radians() / 2.0).tan()
            }
        }
    }

    /// Zooms by `factor` (< 1 closer).
    pub fn zoom(&mut self, factor: f32) {
        self.camera = self.camera.zoomed(factor.clamp(0.05, 20.0));
    }

    /// Looks from a standard direction at the same target and distance.
    pub fn look_from(&mut self, view: StandardView) {
        let (eye, target, _) = parts(&self.camera);
        let d = (eye - target).norm();
        let (dir, up) = match view {
            StandardView::Top => (Vector3::z(), Vector3::y()),
            StandardView::Front => (-Vector3::y(), Vector3::z()),
            StandardView::Side => (Vector3::x(), Vector3::z()),
        };
        self.camera = with_parts(&self.camera, target + d * dir, target, up);
    }

    /// Centres on the bounds and zooms so that they fill the view.
    pub fn frame(&mut self, bounds: ([f32; 3], [f32; 3])) {
        let (eye, target, up) = parts(&self.camera);
        let (lo, hi) = (v3(bounds.0), v3(bounds.1));
        let centre = (lo + hi) / 2.0;
        let radius = ((hi - lo).norm() / 2.0).max(1e-3);
        let dir = (eye - target).normalize();
        self.camera = match self.camera {
            Camera::Perspective { fov_y, .. } => {
                let d = radius / (fov_y.to_radians() / 2.0).sin() * 1.05;
                with_parts(&self.camera, centre + d * dir, centre, up)
            }
            Camera::Orthographic { eye: _, target: _, up: _, .. } => Camera::Orthographic {
                eye: (centre + (eye - target).norm() * dir).into(),
                target: centre.into(),
                up: up.into(),
                half_height: radius * 1.1,
            },
        };
    }

    /// The camera as a scene document writes it (orthographic ones with `half_height`).
    pub fn to_doc(&self) -> CameraDoc {
        let f = |a: [f32; 3]| a.map(f64::from);
        match self.camera {
            Camera::Perspective { eye, target, up, fov_y } => {
                CameraDoc::LookAt { eye: f(eye), target: f(target), up: f(up), fov: fov_y.into(), half_height: None }
            }
            Camera::Orthographic { eye, target, up, half_height } => CameraDoc::LookAt {
                eye: f(eye),
                target: f(target),
                up: f(up),
                fov: 30.0,
                half_height: Some(half_height.into()),
            },
        }
    }
}

/// Projection of world points to pixels of a `size` view and back, with the renderer's
/// matrix for that scene ([`RenderScene::view_projection`]).
#[derive(Debug, Clone, Copy)]
pub struct Projector {
    matrix: Matrix4<f64>,
    inverse: Matrix4<f64>,
    size: (f64, f64),
}

impl Projector {
    /// The projector of the scene as drawn at `size` pixels.
    pub fn new(scene: &RenderScene, size: (u32, u32)) -> Self {
        Self::with_bounds(scene, scene.bounds(), size)
    }

    /// The projector of a scene drawn with these bounds (of layers drawn together,
    /// [`RenderScene::view_projection_in`]).
    pub fn with_bounds(scene: &RenderScene, bounds: Option<([f32; 3], [f32; 3])>, size: (u32, u32)) -> Self {
        let (m, _) = scene.view_projection_in(bounds, size.0.max(1), size.1.max(1));
        let matrix = Matrix4::from_fn(|r, c| f64::from(m[c][r]));
        let inverse = matrix.try_inverse().unwrap_or_else(Matrix4::identity);
        Projector { matrix, inverse, size: (f64::from(size.0), f64::from(size.1)) }
    }

    /// Pixel position (x right, y down, from the view's top-left corner) and normalised
    /// depth of a world point; `None` behind the eye.
    pub fn project(&self, p: [f64; 3]) -> Option<([f64; 2], f64)> {
        let c = self.matrix * Vector4::new(p[0], p[1], p[2], 1.0);
        if c.w <= 1e-12 {
            return None;
        }
        let (x, y, z) = (c.x / c.w, c.y / c.w, c.z / c.w);
        Some(([(x + 1.0) / 2.0 * self.size.0, (1.0 - y) / 2.0 * self.size.1], z))
    }

    /// The world point at pixel `px` and normalised depth `depth`.
    pub fn unproject(&self, px: [f64; 2], depth: f64) -> [f64; 3] {
        let ndc = Vector4::new(2.0 * px[0] / self.size.0 - 1.0, 1.0 - 2.0 * px[1] / self.size.1, depth, 1.0);
        let w = self.inverse * ndc;
        [w.x / w.w, w.y / w.w, w.z / w.w]
    }

    /// The direction the view looks along (world units, unit length).
    pub fn view_direction(&self) -> [f64; 3] {
        let a = self.unproject([self.size.0 / 2.0, self.size.1 / 2.0], 0.2);
        let b = self.unproject([self.size.0 / 2.0, self.size.1 / 2.0], 0.8);
        let d = Vector3::new(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
        let d = d / d.norm().max(1e-300);
        [d.x, d.y, d.z]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_point_projects_and_unprojects_to_itself() {
        let scene =
            RenderScene { camera: Some(Camera::fit(([-1.0; 3], [1.0; 3]), 0.7, 0.4, 1.5)), ..Default::default() };
        let p = Projector::new(&scene, (600, 400));
        let (px, depth) = p.project([0.3, -0.2, 0.5]).expect("in front");
        let back = p.unproject(px, depth);
        for k in 0..3 {
            assert!((back[k] - [0.3, -0.2, 0.5][k]).abs() < 1e-4, "{back:?}");
        }
        let mut cam = ViewCamera::new(Camera::top(([-1.0; 3], [1.0; 3]), 1.0));
        cam.pan(10.0, 0.0, 100.0);
        assert_ne!(cam.camera, cam.home);
        cam.look_from(StandardView::Front);
        assert!(parts(&cam.camera).0.y < parts(&cam.camera).1.y);
    }
}
