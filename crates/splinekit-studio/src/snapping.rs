//! Snapping of a moved handle (each kind toggled in the Snapping panel): onto another
//! handle whose projection is within [`crate::view_caches::PICK_RADIUS`] pixels of the target's,
//! else onto a coordinate axis whose projection is that close (the nearest point of the
//! axis line), and then each coordinate (along the axis: that one) to a multiple of the
//! grid step. The step is also what the arrow keys nudge a selection by.

use crate::view_caches::PICK_RADIUS;
use crate::view_camera::Projector;

/// What a moved handle snaps to, and the step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Snapping {
    /// Round coordinates to multiples of `step`.
    pub grid: bool,
    /// Onto other handles.
    pub handles: bool,
    /// Onto the x, y and z axes.
    pub axes: bool,
    /// The grid step and the nudge of the arrow keys (world units).
    pub step: f64,
}

impl Default for Snapping {
    fn default() -> Self {
        Snapping { grid: false, handles: false, axes: false, step: 0.1 }
    }
}

fn round_to(x: f64, step: f64) -> f64 {
    if step > 0.0 { (x / step).round() * step } else { x }
}

impl Snapping {
    /// Whether anything snaps.
    pub fn any(&self) -> bool {
        self.grid || self.handles || self.axes
    }

    /// Where a handle moved to `p` (`dimension` coordinates) lands: onto one of `targets`
    /// (other handles' positions) within the pick radius on screen, else onto an axis
    /// within it, then on the grid.
    pub fn snap(&self, p: [f64; 3], dimension: usize, targets: &[[f64; 3]], projector: &Projector) -> [f64; 3] {
        let screen = |q: [f64; 3]| projector.project(q).map(|(s, _)| s);
        let near = |q: [f64; 3]| match (screen(p), screen(q)) {
            (Some(a), Some(b)) => (a[0] - b[0]).hypot(a[1] - b[1]) <= PICK_RADIUS,
            _ => false,
        };
        if self.handles
            && let Some(t) = targets.iter().copied().filter(|&t| near(t)).min_by(|a, b| {
                let d = |q: &[f64; 3]| (0..3).map(|i| (q[i] - p[i]).powi(2)).sum::<f64>();
                d(a).total_cmp(&d(b))
            })
        {
            return t;
        }
        let mut q = p;
        let mut free = [true; 3];
        if self.axes {
            let axis = (0..dimension.min(3)).map(|k| [0, 1, 2].map(|i| if i == k { p[i] } else { 0.0 })).enumerate();
            if let Some((k, on)) = axis.filter(|&(_, on)| near(on)).min_by(|a, b| {
                let d = |q: &[f64; 3]| (0..3).map(|i| (q[i] - p[i]).powi(2)).sum::<f64>();
                d(&a.1).total_cmp(&d(&b.1))
            }) {
                q = on;
                free = [0, 1, 2].map(|i| i == k);
            }
        }
        if self.grid {
            for (x, _) in q.iter_mut().zip(free).take(dimension.min(3)).filter(|(_, f)| *f) {
                *x = round_to(*x, self.step);
            }
        }
        q
    }
}

/// The Snapping panel: the toggles and the step.
pub fn snapping_panel(ui: &mut egui::Ui, snapping: &mut Snapping) {
    ui.heading("Snapping");
    ui.horizontal_wrapped(|ui| {
        ui.checkbox(&mut snapping.grid, "grid");
        ui.checkbox(&mut snapping.handles, "handles");
        ui.checkbox(&mut snapping.axes, "axes");
    });
    ui.horizontal(|ui| {
        let name = ui.label("step");
        ui.add(egui::DragValue::new(&mut snapping.step).range(1e-6..=1e6).speed(0.01)).labelled_by(name.id);
    });
    ui.label("arrow keys nudge the selection by the step (Shift: ×10)");
}

#[cfg(test)]
mod tests {
    use super::*;
    use splinekit_render::{Camera, RenderScene};

    fn top_view() -> Projector {
        let mut scene = RenderScene::default();
        let mut cam = crate::view_camera::ViewCamera::new(Camera::fit(([-2.0; 3], [2.0; 3]), 0.9, 0.5, 1.0));
        cam.look_from(crate::view_camera::StandardView::Top);
        scene.camera = Some(cam.camera);
        Projector::new(&scene, (400, 400))
    }

    #[test]
    fn snaps_to_handles_then_axes_then_the_grid() {
        let projector = top_view();
        let s = Snapping { grid: true, handles: true, axes: true, step: 0.25 };
        // Far from the axes and handles: the grid.
        assert_eq!(s.snap([0.93, 1.12, 0.0], 2, &[], &projector), [1.0, 1.0, 0.0]);
        // Close to another handle: onto it.
        let other = [0.9301, 1.1201, 0.0];
        assert_eq!(s.snap([0.93, 1.12, 0.0], 2, &[other], &projector), other);
        // A pixel from the x axis: onto it, and along it on the grid.
        assert_eq!(s.snap([0.93, 0.004, 0.0], 2, &[], &projector), [1.0, 0.0, 0.0]);
        let off = Snapping { grid: false, handles: false, axes: false, step: 0.25 };
        assert_eq!(off.snap([0.93, 0.004, 0.0], 2, &[other], &projector), [0.93, 0.004, 0.0]);
    }
}
