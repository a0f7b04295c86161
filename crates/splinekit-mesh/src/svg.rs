//! SVG drawings of curves, points and labels, in 2-D or projected from 3-D.
//!
//! World coordinates are mapped to pixels by one uniform scale fitted to the bounds of
//! everything drawn (y up), so shapes keep their proportions; line widths and point radii
//! are in pixels.

use splinekit::Point;
use std::fmt::Write;

use crate::export::representable::{ExportError, Precision, check_value};

/// How world points map to the drawing plane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Projection {
    /// Image of the first three world axes on the drawing's x.
    pub x: [f64; 3],
    /// Image of the world axes on the drawing's y.
    pub y: [f64; 3],
}

impl Projection {
    /// Drop z: (x, y, z) ↦ (x, y).
    pub const TOP: Projection = Projection { x: [1.0, 0.0, 0.0], y: [0.0, 1.0, 0.0] };

    /// Orthographic view from azimuth `az` (about z) and elevation `el` (radians).
    pub fn view(az: f64, el: f64) -> Self {
        let (sa, ca) = az.sin_cos();
        let (se, ce) = el.sin_cos();
        // Camera right = (−sin az, cos az, 0); up = (−cos az sin el, −sin az sin el, cos el).
        Projection { x: [-sa, ca, 0.0], y: [-ca * se, -sa * se, ce] }
    }

    /// Projects a point of any dimension (missing coordinates are 0).
    pub fn apply<const D: usize>(&self, p: &Point<D>) -> [f64; 2] {
        let c = |i: usize| if i < D { p[i] } else { 0.0 };
        let (x, y, z) = (c(0), c(1), c(2));
        [self.x[0] * x + self.x[1] * y + self.x[2] * z, self.y[0] * x + self.y[1] * y + self.y[2] * z]
    }
}

#[derive(Debug, Clone)]
enum Item {
    Path { pts: Vec<[f64; 2]>, closed: bool, stroke: String, width: f64, dash: Option<String> },
    Dots { pts: Vec<[f64; 2]>, radius: f64, fill: String },
    Label { at: [f64; 2], text: String, colour: String },
}

/// A drawing under construction.
#[derive(Debug, Clone)]
pub struct SvgFigure {
    width: f64,
    height: f64,
    projection: Projection,
    title: String,
    items: Vec<Item>,
}

impl SvgFigure {
    /// An empty drawing of the given pixel size.
    pub fn new(width: f64, height: f64, projection: Projection) -> Self {
        SvgFigure { width, height, projection, title: String::new(), items: Vec::new() }
    }
    /// A title drawn at the top.
    pub fn title(mut self, title: &str) -> Self {
        self.title = title.to_string();
        self
    }
    /// A polyline through `points` (closed: back to the first).
    pub fn path<const D: usize>(&mut self, points: &[Point<D>], closed: bool, stroke: &str, width: f64) -> &mut Self {
        let pts = points.iter().map(|p| self.projection.apply(p)).collect();
        self.items.push(Item::Path { pts, closed, stroke: stroke.into(), width, dash: None });
        self
    }
    /// A dashed polyline (control polygons).
    pub fn dashed<const D: usize>(&mut self, points: &[Point<D>], closed: bool, stroke: &str, width: f64) -> &mut Self {
        let pts = points.iter().map(|p| self.projection.apply(p)).collect();
        self.items.push(Item::Path { pts, closed, stroke: stroke.into(), width, dash: Some("6 4".into()) });
        self
    }
    /// Filled dots of `radius` pixels.
    pub fn dots<const D: usize>(&mut self, points: &[Point<D>], radius: f64, fill: &str) -> &mut Self {
        let pts = points.iter().map(|p| self.projection.apply(p)).collect();
        self.items.push(Item::Dots { pts, radius, fill: fill.into() });
        self
    }
    /// A text label at a world point.
    pub fn label<const D: usize>(&mut self, at: &Point<D>, text: &str, colour: &str) -> &mut Self {
        self.items.push(Item::Label { at: self.projection.apply(at), text: text.into(), colour: colour.into() });
        self
    }

    /// The SVG document; refuses points whose drawing coordinates are not finite (NaN,
    /// infinite, or so far apart that the picture's scale overflows), naming the item.
    pub fn render(&self) -> Result<String, ExportError> {
        let view = self.viewport();
        self.check_drawable(&view)?;
        let mut s = String::new();
        let _ = writeln!(
            s,
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{}" height="{}" viewBox="0 0 {} {}">"#,
            self.width, self.height, self.width, self.height
        );
        let _ = writeln!(s, r#"<rect width="100%" height="100%" fill="white"/>"#);
        if !self.title.is_empty() {
            let _ = writeln!(
                s,
                r#"<text x="{}" y="22" font-family="sans-serif" font-size="16" text-anchor="middle">{}</text>"#,
                self.width / 2.0,
                escape(&self.title)
            );
        }
        for item in &self.items {
            write_item(&mut s, item, &view);
        }
        s.push_str("</svg>\n");
        Ok(s)
    }

    /// The map from projected points to the picture: their finite bounding box fitted into
    /// the page below the title, with a margin, keeping the aspect ratio.
    fn viewport(&self) -> Viewport {
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in self.items.iter().flat_map(Item::points) {
            for i in 0..2 {
                if p[i].is_finite() {
                    lo[i] = lo[i].min(p[i]);
                    hi[i] = hi[i].max(p[i]);
                }
            }
        }
        if !lo[0].is_finite() {
            lo = [0.0, 0.0];
            hi = [1.0, 1.0];
        }
        let top = if self.title.is_empty() { 0.0 } else { 28.0 };
        let margin = 20.0;
        let (w, h) = (self.width - 2.0 * margin, self.height - 2.0 * margin - top);
        let span = [(hi[0] - lo[0]).max(1e-12), (hi[1] - lo[1]).max(1e-12)];
        let scale = (w / span[0]).min(h / span[1]);
        let origin = [margin + (w - span[0] * scale) / 2.0, margin + top + (h - span[1] * scale) / 2.0];
        Viewport { origin, scale, left: lo[0], top: hi[1] }
    }

    /// Refuses an item point whose picture coordinates are not finite.
    fn check_drawable(&self, view: &Viewport) -> Result<(), ExportError> {
        for (k, item) in self.items.iter().enumerate() {
            for (i, p) in item.points().iter().enumerate() {
                for (c, &x) in view.map(p).iter().enumerate() {
                    check_value(x, Precision::Double, "SVG", || {
                        format!("items[{k}] point {i} ({:?}) drawn at [{c}]", p)
                    })?;
                }
            }
        }
        Ok(())
    }
}

impl Item {
    /// The projected points the item draws (a label: its anchor).
    fn points(&self) -> &[[f64; 2]] {
        match self {
            Item::Path { pts, .. } | Item::Dots { pts, .. } => pts.as_slice(),
            Item::Label { at, .. } => std::slice::from_ref(at),
        }
    }
}

/// Projected points → picture coordinates: origin + scale · (x − left, top − y).
struct Viewport {
    origin: [f64; 2],
    scale: f64,
    left: f64,
    top: f64,
}

impl Viewport {
    fn map(&self, p: &[f64; 2]) -> [f64; 2] {
        [self.origin[0] + (p[0] - self.left) * self.scale, self.origin[1] + (self.top - p[1]) * self.scale]
    }
}

/// One item as SVG elements.
fn write_item(s: &mut String, item: &Item, view: &Viewport) {
    match item {
        Item::Path { pts, closed, stroke, width, dash } => {
            let mut d = String::new();
            for (i, p) in pts.iter().enumerate() {
                let q = view.map(p);
                let _ = write!(d, "{}{:.2},{:.2} ", if i == 0 { "M" } else { "L" }, q[0], q[1]);
            }
            if *closed {
                d.push('Z');
            }
            let dash = dash.as_ref().map(|d| format!(r#" stroke-dasharray="{d}""#)).unwrap_or_default();
            let _ = writeln!(
                s,
                r#"<path d="{}" fill="none" stroke="{stroke}" stroke-width="{width}" stroke-linejoin="round"{dash}/>"#,
                d.trim_end()
            );
        }
        Item::Dots { pts, radius, fill } => {
            for p in pts {
                let q = view.map(p);
                let _ = writeln!(s, r#"<circle cx="{:.2}" cy="{:.2}" r="{radius}" fill="{fill}"/>"#, q[0], q[1]);
            }
        }
        Item::Label { at, text, colour } => {
            let q = view.map(at);
            let _ = writeln!(
                s,
                r#"<text x="{:.2}" y="{:.2}" font-family="sans-serif" font-size="13" fill="{colour}">{}</text>"#,
                q[0] + 6.0,
                q[1] - 6.0,
                escape(text)
            );
        }
    }
}

fn escape(t: &str) -> String {
    t.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}
