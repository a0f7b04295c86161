//! Scene documents: shapes with styles, a camera, lights and an animation clock.
//!
//! ```json
//! {"type": "scene",
//!  "objects": [{"shape": {…}, "color": [0.2, 0.4, 0.8], "wireframe": true}],
//!  "camera": {"azimuth": 40, "elevation": 30},
//!  "size": [800, 600],
//!  "animation": {"duration": 1, "fps": 20}}
//! ```

use serde::{Deserialize, Deserializer, Serialize};
use serde_json::Value;

use crate::ShapeDocument;
use crate::error::{DocumentError, Result};
use crate::json::{fields, kind, nested, split_type};
use crate::placement::PlacementDoc;

fn default_line_width() -> f64 {
    2.5
}

/// How an object is drawn.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StyleDoc {
    /// sRGB colour [r, g, b] or [r, g, b, a] in [0, 1] (default: from a palette by index).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub color: Option<Vec<f64>>,
    /// Width of curves in pixels (default 2.5).
    #[serde(default = "default_line_width")]
    pub line_width: f64,
    /// Surfaces: draw parameter lines over the shading.
    #[serde(default)]
    pub wireframe: bool,
    /// Control polygons and nets (B-spline, NURBS, Bézier) with their points.
    #[serde(default)]
    pub control_net: bool,
    /// Blending splines: draw the local curves or patches in their own colours.
    #[serde(default)]
    pub local_pieces: bool,
    /// Colour by a quantity ([`ColorMapDoc`]): surfaces by a curvature, a coordinate, a
    /// parameter or a speed, or `zebra` stripes or `isophotes` (reflection lines to read
    /// continuity from); curves by a coordinate, their parameter, speed, curvature or
    /// torsion.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub color_map: Option<ColorMapDoc>,
    /// Short arrows of a vector field of the shape (normals, partials, derivatives), at
    /// regular parameters over all of it or only on its boundary.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub arrows: Option<ArrowsDoc>,
    /// Grid cells per direction for surfaces, segments for curves (default: adaptive
    /// curves, 64 surface cells).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub density: Option<usize>,
    /// Hide the shape itself (e.g. to show only its control net or local pieces).
    #[serde(default)]
    pub hidden: bool,
    /// Turn the colour's hue once per run of the animation clock (the seed's HSV colour
    /// cycling of the beating heart); without a time, the colour as given.
    #[serde(default, skip_serializing_if = "crate::defaults::is_false")]
    pub color_cycle: bool,
}

impl StyleDoc {
    /// Checks the ranges serde does not: colour, line width and density.
    fn check(&self) -> Result<()> {
        if let Some(c) = &self.color
            && (!(3..=4).contains(&c.len()) || c.iter().any(|x| !(0.0..=1.0).contains(x)))
        {
            return Err(DocumentError::new("color", format!("expected 3 or 4 numbers in [0, 1], got {c:?}")));
        }
        if !(self.line_width > 0.0 && self.line_width <= 64.0) {
            return Err(DocumentError::new(
                "line_width",
                format!("must be in (0, 64] pixels, got {}", self.line_width),
            ));
        }
        if let Some(d) = self.density
            && !(1..=2048).contains(&d)
        {
            return Err(DocumentError::new("density", format!("must be between 1 and 2048, got {d}")));
        }
        if let Some(a) = &self.arrows {
            a.check().map_err(|e| e.within("arrows"))?;
        }
        Ok(())
    }
}

impl Default for StyleDoc {
    fn default() -> Self {
        StyleDoc {
            color: None,
            line_width: default_line_width(),
            wireframe: false,
            control_net: false,
            local_pieces: false,
            color_map: None,
            arrows: None,
            density: None,
            hidden: false,
            color_cycle: false,
        }
    }
}

/// Colour maps of curves and surfaces.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ColorMapDoc {
    /// Gaussian curvature (blue negative, white zero, red positive; surfaces).
    Gaussian,
    /// Mean curvature (surfaces).
    Mean,
    /// The larger principal curvature κ₁ (surfaces).
    PrincipalMax,
    /// The smaller principal curvature κ₂ (surfaces).
    PrincipalMin,
    /// The curvature κ of a curve.
    Curvature,
    /// The torsion τ of a 3-D curve (blue negative, white zero, red positive).
    Torsion,
    /// The x coordinate (dark blue at its least, yellow at its most over the shape).
    X,
    /// The y coordinate.
    Y,
    /// The z coordinate.
    Z,
    /// The u parameter (a curve's parameter t), over its domain.
    U,
    /// The v parameter (surfaces).
    V,
    /// The speed in u, |S_u| (a curve's |c′|), from 0 to its most over the shape.
    SpeedU,
    /// The speed in v, |S_v| (surfaces).
    SpeedV,
    /// Black and white stripes of the angle of the normal from the yz-plane, 15° each: the
    /// reflection of parallel light bars; kinks in the stripes show tangent (G1) breaks,
    /// sudden turns curvature (G2) breaks (surfaces).
    Zebra,
    /// Thin dark lines where N·L is a multiple of 0.1 for a fixed light L ∝ (1, 1, 2), on the
    /// shape's colour (surfaces).
    Isophotes,
}

impl ColorMapDoc {
    /// Every colour map, in the order the studio offers them.
    pub const ALL: [ColorMapDoc; 15] = [
        ColorMapDoc::Gaussian,
        ColorMapDoc::Mean,
        ColorMapDoc::PrincipalMax,
        ColorMapDoc::PrincipalMin,
        ColorMapDoc::Curvature,
        ColorMapDoc::Torsion,
        ColorMapDoc::X,
        ColorMapDoc::Y,
        ColorMapDoc::Z,
        ColorMapDoc::U,
        ColorMapDoc::V,
        ColorMapDoc::SpeedU,
        ColorMapDoc::SpeedV,
        ColorMapDoc::Zebra,
        ColorMapDoc::Isophotes,
    ];

    /// The name in documents.
    pub fn name(self) -> &'static str {
        match self {
            ColorMapDoc::Gaussian => "gaussian",
            ColorMapDoc::Mean => "mean",
            ColorMapDoc::PrincipalMax => "principal_max",
            ColorMapDoc::PrincipalMin => "principal_min",
            ColorMapDoc::Curvature => "curvature",
            ColorMapDoc::Torsion => "torsion",
            ColorMapDoc::X => "x",
            ColorMapDoc::Y => "y",
            ColorMapDoc::Z => "z",
            ColorMapDoc::U => "u",
            ColorMapDoc::V => "v",
            ColorMapDoc::SpeedU => "speed_u",
            ColorMapDoc::SpeedV => "speed_v",
            ColorMapDoc::Zebra => "zebra",
            ColorMapDoc::Isophotes => "isophotes",
        }
    }

    /// Whether the map colours curves: x, y, z, u, speed_u, curvature, torsion.
    pub fn for_curves(self) -> bool {
        matches!(
            self,
            ColorMapDoc::X
                | ColorMapDoc::Y
                | ColorMapDoc::Z
                | ColorMapDoc::U
                | ColorMapDoc::SpeedU
                | ColorMapDoc::Curvature
                | ColorMapDoc::Torsion
        )
    }

    /// Whether the map colours surfaces: every map but curvature and torsion.
    pub fn for_surfaces(self) -> bool {
        !matches!(self, ColorMapDoc::Curvature | ColorMapDoc::Torsion)
    }

    /// The maps a curve (`surface` false) or a surface takes, for messages.
    pub fn names_for(surface: bool) -> String {
        let names: Vec<&str> = Self::ALL
            .iter()
            .filter(|m| if surface { m.for_surfaces() } else { m.for_curves() })
            .map(|m| m.name())
            .collect();
        names.join(", ")
    }
}

/// `"arrows": {"field": "normal", "on": "all", "count": 12, "length": 0.08}`: short arrows
/// of a vector field at regular parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ArrowsDoc {
    /// The field drawn.
    pub field: ArrowFieldDoc,
    /// Where: over the whole shape (default) or only on its boundary.
    #[serde(default)]
    pub on: ArrowPlacementDoc,
    /// Arrows per direction: along a curve, along each side of a surface (default 32 for
    /// curves, 12 for surfaces; 1 … 256).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub count: Option<usize>,
    /// The longest arrow's length as a fraction of the shape's size (its box's diagonal;
    /// default 0.08, at most 1).
    #[serde(default = "default_arrow_length")]
    pub length: f64,
}

fn default_arrow_length() -> f64 {
    0.08
}

impl ArrowsDoc {
    fn check(&self) -> Result<()> {
        if let Some(n) = self.count
            && !(1..=256).contains(&n)
        {
            return Err(DocumentError::new("count", format!("must be between 1 and 256, got {n}")));
        }
        if !(self.length > 0.0 && self.length <= 1.0) {
            return Err(DocumentError::new("length", format!("must be in (0, 1], got {}", self.length)));
        }
        Ok(())
    }
}

/// Which vector field arrows show.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ArrowFieldDoc {
    /// Surfaces: the unit normal S_u × S_v/|…|; curves: the unit principal normal.
    Normal,
    /// Curves: the unit tangent c′/|c′|.
    Tangent,
    /// Curves: the first derivative c′, to scale.
    Derivative,
    /// Curves: the second derivative c″, to scale.
    Second,
    /// Surfaces: S_u, to scale.
    Du,
    /// Surfaces: S_v, to scale.
    Dv,
    /// Surfaces: the twist S_uv, to scale.
    Duv,
}

impl ArrowFieldDoc {
    /// Every field, in the order the studio offers them.
    pub const ALL: [ArrowFieldDoc; 7] = [
        ArrowFieldDoc::Normal,
        ArrowFieldDoc::Tangent,
        ArrowFieldDoc::Derivative,
        ArrowFieldDoc::Second,
        ArrowFieldDoc::Du,
        ArrowFieldDoc::Dv,
        ArrowFieldDoc::Duv,
    ];

    /// The name in documents.
    pub fn name(self) -> &'static str {
        match self {
            ArrowFieldDoc::Normal => "normal",
            ArrowFieldDoc::Tangent => "tangent",
            ArrowFieldDoc::Derivative => "derivative",
            ArrowFieldDoc::Second => "second",
            ArrowFieldDoc::Du => "du",
            ArrowFieldDoc::Dv => "dv",
            ArrowFieldDoc::Duv => "duv",
        }
    }

    /// Whether curves have the field (normal, tangent, derivative, second).
    pub fn for_curves(self) -> bool {
        matches!(
            self,
            ArrowFieldDoc::Normal | ArrowFieldDoc::Tangent | ArrowFieldDoc::Derivative | ArrowFieldDoc::Second
        )
    }

    /// Whether surfaces have the field (normal, du, dv, duv).
    pub fn for_surfaces(self) -> bool {
        matches!(self, ArrowFieldDoc::Normal | ArrowFieldDoc::Du | ArrowFieldDoc::Dv | ArrowFieldDoc::Duv)
    }

    /// Whether arrows show the direction only (unit length), not the magnitude.
    pub fn is_unit(self) -> bool {
        matches!(self, ArrowFieldDoc::Normal | ArrowFieldDoc::Tangent)
    }
}

/// Where arrows are drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ArrowPlacementDoc {
    /// At regular parameters over the whole domain.
    #[default]
    All,
    /// Only on the boundary: a surface's four sides, a curve's two ends.
    Boundary,
}

/// One object of a scene: `{"shape": {…}, "points": [[x, y, z], …], …style…}`.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneObject {
    /// The shape.
    pub shape: ShapeDocument,
    /// How it is drawn.
    pub style: StyleDoc,
    /// Extra points to mark (e.g. data points), drawn as discs in the object's colour.
    pub points: Vec<[f64; 3]>,
    /// `"model_of": k`: a blending spline whose model is object k's shape, a live link
    /// that [`SceneDocument::resolve_models`] follows (the shape's `model` is then a copy
    /// of object k's shape, made again whenever the scene is read or edited).
    pub model_of: Option<usize>,
    /// `"placement": {…}`: the shape drawn moved rigidly (see [`crate::placement`]).
    pub placement: Option<PlacementDoc>,
    /// `"instance_of": k`: the object is another use of object k's shape (a part used
    /// several times in an assembly), written without a `shape` of its own;
    /// [`SceneDocument::resolve_instances`] fills `shape` in.
    pub instance_of: Option<usize>,
    /// `"name"`: what the object is called (a part's occurrence in an assembly), carried
    /// into glTF nodes and STEP items.
    pub name: Option<String>,
}

impl SceneObject {
    /// Parses an object: its `shape`, its `points`, and the other fields as its style.
    pub fn from_value(value: Value) -> Result<Self> {
        let Value::Object(mut style) = value else {
            return Err(DocumentError::new("", format!("expected an object with a \"shape\", got {}", kind(&value))));
        };
        let index = |field: &str, v: Option<Value>| -> Result<Option<usize>> {
            match v {
                None | Some(Value::Null) => Ok(None),
                Some(v) => Ok(Some(v.as_u64().and_then(|k| usize::try_from(k).ok()).ok_or_else(|| {
                    DocumentError::new(field, format!("expected the index of an object of the scene, got {v}"))
                })?)),
            }
        };
        let instance_of = index("instance_of", style.remove("instance_of"))?;
        let name = match style.remove("name") {
            None | Some(Value::Null) => None,
            Some(Value::String(n)) => Some(n),
            Some(v) => return Err(DocumentError::new("name", format!("expected a string, got {}", kind(&v)))),
        };
        let placement: Option<PlacementDoc> = match style.remove("placement") {
            None | Some(Value::Null) => None,
            Some(p) => {
                let p: PlacementDoc = fields(p).map_err(|e| e.within("placement"))?;
                p.transform().map_err(|e| e.within("placement"))?;
                Some(p)
            }
        };
        let shape = match (style.remove("shape"), instance_of) {
            (Some(_), Some(k)) => {
                return Err(DocumentError::new(
                    "instance_of",
                    format!("an instance of object {k} takes its shape; give `shape` or `instance_of`, not both"),
                ));
            }
            (Some(shape), None) => shape,
            // A stand-in until the scene gives the instance object k's shape.
            (None, Some(_)) => serde_json::json!({"type": "line", "from": [0, 0, 0], "to": [1, 0, 0]}),
            (None, None) => return Err(DocumentError::new("", "missing field `shape`")),
        };
        let model_of = index("model_of", style.remove("model_of"))?;
        // A linked model is filled in by the scene (`SceneDocument::resolve_models`); until
        // then a stand-in of the family keeps the shape readable.
        let mut shape = shape;
        if model_of.is_some()
            && let Some(fields) = shape.as_object_mut()
            && !fields.contains_key("model")
        {
            let stand_in = match fields.get("type").and_then(Value::as_str) {
                Some("blending_spline") => Some(serde_json::json!({"type": "circle"})),
                Some("blending_spline_surface") => Some(serde_json::json!({"type": "torus"})),
                _ => None,
            };
            if let Some(m) = stand_in {
                fields.insert("model".into(), m);
            }
        }
        let points: Vec<Vec<f64>> = match style.remove("points") {
            Some(p) => fields(p).map_err(|e| e.within("points"))?,
            None => Vec::new(),
        };
        let shape = ShapeDocument::from_value(shape).map_err(|e| e.within("shape"))?;
        let style: StyleDoc = fields(Value::Object(style))?;
        style.check()?;
        let points = points
            .iter()
            .enumerate()
            .map(|(i, p)| {
                if !(2..=3).contains(&p.len()) || p.iter().any(|x| !x.is_finite()) {
                    return Err(DocumentError::new(format!("points[{i}]"), "expected 2 or 3 finite coordinates"));
                }
                Ok([p[0], p[1], p.get(2).copied().unwrap_or(0.0)])
            })
            .collect::<Result<_>>()?;
        Ok(SceneObject { shape, style, points, model_of, placement, instance_of, name })
    }
}

impl SceneObject {
    /// `{"shape": {…}, …style…, "points": […]}`, as [`SceneObject`] parses it.
    pub fn to_value(&self) -> Value {
        let mut doc = match serde_json::to_value(&self.style) {
            Ok(Value::Object(m)) => m,
            _ => serde_json::Map::new(),
        };
        let shape = match &self.shape {
            ShapeDocument::Curve(c) => c.to_value(),
            ShapeDocument::Surface(s) => s.to_value(),
        };
        match self.instance_of {
            Some(k) => doc.insert("instance_of".into(), k.into()),
            None => doc.insert("shape".into(), shape),
        };
        if let Some(p) = &self.placement {
            doc.insert("placement".into(), serde_json::to_value(p).unwrap_or_default());
        }
        if let Some(n) = &self.name {
            doc.insert("name".into(), n.clone().into());
        }
        if !self.points.is_empty() {
            doc.insert("points".into(), serde_json::json!(self.points));
        }
        if let Some(k) = self.model_of {
            doc.insert("model_of".into(), k.into());
        }
        Value::Object(doc)
    }
}

impl<'de> Deserialize<'de> for SceneObject {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> std::result::Result<Self, D::Error> {
        nested(deserializer, SceneObject::from_value)
    }
}

/// The camera of a scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(untagged, deny_unknown_fields)]
pub enum CameraDoc {
    /// Look at the scene from `eye` towards `target`.
    LookAt {
        /// Eye position.
        eye: [f64; 3],
        /// Point looked at.
        target: [f64; 3],
        /// Up direction (default z).
        #[serde(default = "z_up")]
        up: [f64; 3],
        /// Vertical field of view in degrees (default 30).
        #[serde(default = "thirty")]
        fov: f64,
        /// Orthographic instead: half the visible height in world units (`fov` unused).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        half_height: Option<f64>,
    },
    /// Fitted to the scene, from a direction in degrees (`top: true`: orthographic from +z).
    Orbit {
        /// Degrees about z from +x (default 50).
        #[serde(default = "fifty")]
        azimuth: f64,
        /// Degrees above the xy-plane (default 28).
        #[serde(default = "twenty_eight")]
        elevation: f64,
        /// Orthographic view from above (plane figures).
        #[serde(default)]
        top: bool,
    },
}

fn z_up() -> [f64; 3] {
    [0.0, 0.0, 1.0]
}
fn thirty() -> f64 {
    30.0
}
fn fifty() -> f64 {
    50.0
}
fn twenty_eight() -> f64 {
    28.0
}

/// A light shining towards `direction`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LightDoc {
    /// Direction the light travels.
    pub direction: [f64; 3],
    /// Intensity (default 0.7).
    #[serde(default = "seven_tenths")]
    pub intensity: f64,
}

fn seven_tenths() -> f64 {
    0.7
}

/// The animation clock of a scene.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct AnimationDoc {
    /// Length in seconds (default 1).
    pub duration: f64,
    /// Frames per second (default 20).
    pub fps: f64,
}

impl Default for AnimationDoc {
    fn default() -> Self {
        AnimationDoc { duration: 1.0, fps: 20.0 }
    }
}

impl AnimationDoc {
    /// Frames in one run of the clock at `fps` frames per second (at least one).
    pub fn frames_at(&self, fps: f64) -> usize {
        (self.duration * fps).round().max(1.0) as usize
    }
    /// Frames in one run of the clock at its own rate.
    pub fn frames(&self) -> usize {
        self.frames_at(self.fps)
    }
}

/// A scene document.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneDocument {
    /// The objects.
    pub objects: Vec<SceneObject>,
    /// The camera (default: fitted, from azimuth 50°, elevation 28°; plane scenes from the top).
    #[serde(default)]
    pub camera: Option<CameraDoc>,
    /// Up to two lights (default: two fixed lights).
    #[serde(default)]
    pub lights: Vec<LightDoc>,
    /// Background sRGB colour (default white).
    #[serde(default = "white", deserialize_with = "white_if_null")]
    pub background: [f64; 3],
    /// Image size in pixels (default 800×600).
    #[serde(default = "default_size", deserialize_with = "default_size_if_null")]
    pub size: [u32; 2],
    /// Draw x, y, z axes.
    #[serde(default)]
    pub axes: bool,
    /// The animation clock as the document gives it (`None`: none given, the default
    /// clock of [`SceneDocument::clock`]; kept apart so that writing the scene back adds
    /// no block the document did not have).
    #[serde(default, deserialize_with = "animation_or_null")]
    pub animation: Option<AnimationDoc>,
}

fn white() -> [f64; 3] {
    [1.0, 1.0, 1.0]
}
fn default_size() -> [u32; 2] {
    [800, 600]
}
fn white_if_null<'de, D: Deserializer<'de>>(d: D) -> std::result::Result<[f64; 3], D::Error> {
    Ok(Option::deserialize(d)?.unwrap_or_else(white))
}
fn default_size_if_null<'de, D: Deserializer<'de>>(d: D) -> std::result::Result<[u32; 2], D::Error> {
    Ok(Option::deserialize(d)?.unwrap_or_else(default_size))
}
fn animation_or_null<'de, D: Deserializer<'de>>(d: D) -> std::result::Result<Option<AnimationDoc>, D::Error> {
    Option::deserialize(d)
}

/// Largest image side of a scene.
pub const MAX_SIZE: u32 = 8192;

impl SceneDocument {
    /// Parses `{"type":"scene",…}`.
    pub fn parse(value: &Value) -> Result<Self> {
        Self::from_value(value.clone())
    }

    /// Parses `{"type":"scene",…}`, taking the JSON value.
    pub fn from_value(value: Value) -> Result<Self> {
        let (ty, rest) = split_type(value)?;
        if ty != "scene" {
            return Err(DocumentError::new("type", format!("expected \"scene\", got \"{ty}\"")));
        }
        let mut scene: SceneDocument = fields(rest)?;
        scene.check()?;
        scene.resolve_models()?;
        Ok(scene)
    }

    /// Gives every object with `instance_of: k` object k's shape. Object k must be another
    /// object of the scene with a shape of its own (instances are of parts, not of other
    /// instances); errors name `objects[i].instance_of`.
    pub fn resolve_instances(&mut self) -> Result<()> {
        let n = self.objects.len();
        for i in 0..n {
            let Some(k) = self.objects[i].instance_of else { continue };
            let field = || format!("objects[{i}].instance_of");
            if k >= n || k == i {
                let why = if k == i {
                    "an object cannot be an instance of itself".to_string()
                } else {
                    format!("the scene has {n} objects")
                };
                return Err(DocumentError::new(field(), format!("{k}: {why}")));
            }
            if let Some(j) = self.objects[k].instance_of {
                return Err(DocumentError::new(
                    field(),
                    format!("{k}: object {k} is itself an instance (of object {j}); name the object with the shape"),
                ));
            }
            self.objects[i].shape = self.objects[k].shape.clone();
        }
        Ok(())
    }

    /// Follows the live links: every object with `model_of: k` gets object k's shape (as
    /// it is now, itself resolved first) as its `model`. Object k must be another object of
    /// the scene, of the family the blending spline blends (a curve for `blending_spline`,
    /// a surface for `blending_spline_surface`), and the links must not run in a circle;
    /// errors name `objects[i].model_of`. Instances are resolved first
    /// ([`Self::resolve_instances`]). Reading a scene resolves it; the studio resolves
    /// it again after every edit, so the blending spline follows its model's edits.
    pub fn resolve_models(&mut self) -> Result<()> {
        self.resolve_instances()?;
        let n = self.objects.len();
        // Depth-first from each linked object, models before the objects that take them.
        let mut order = Vec::new();
        let mut state = vec![0u8; n]; // 0 new, 1 on the path, 2 done
        for start in 0..n {
            let mut path = vec![start];
            while let Some(&i) = path.last() {
                if state[i] == 2 {
                    path.pop();
                    continue;
                }
                let field = format!("objects[{i}].model_of");
                match self.objects[i].model_of {
                    Some(k) if k >= n || k == i => {
                        let why = if k == i {
                            "an object cannot be its own model".to_string()
                        } else {
                            format!("the scene has {n} objects")
                        };
                        return Err(DocumentError::new(field, format!("{k}: {why}")));
                    }
                    Some(k) if state[k] == 1 => {
                        return Err(DocumentError::new(
                            field,
                            format!("the models run in a circle through objects {i} and {k}"),
                        ));
                    }
                    Some(k) if state[k] == 0 => {
                        state[i] = 1;
                        path.push(k);
                    }
                    _ => {
                        state[i] = 2;
                        order.push(i);
                        path.pop();
                    }
                }
            }
        }
        for i in order {
            let Some(k) = self.objects[i].model_of else { continue };
            let model = self.objects[k].shape.clone();
            let field = || format!("objects[{i}].model_of");
            match (&mut self.objects[i].shape, model) {
                (ShapeDocument::Curve(crate::curves::CurveDocument::BlendingSpline(d)), ShapeDocument::Curve(c)) => {
                    d.model = Some(Box::new(c));
                }
                (
                    ShapeDocument::Surface(crate::surfaces::SurfaceDocument::BlendingSplineSurface(d)),
                    ShapeDocument::Surface(m),
                ) => {
                    d.model = Some(Box::new(m));
                }
                (ShapeDocument::Curve(crate::curves::CurveDocument::BlendingSpline(_)), _) => {
                    return Err(DocumentError::new(
                        field(),
                        format!("object {k} is a surface; a blending_spline takes a curve"),
                    ));
                }
                (ShapeDocument::Surface(crate::surfaces::SurfaceDocument::BlendingSplineSurface(_)), _) => {
                    return Err(DocumentError::new(
                        field(),
                        format!("object {k} is a curve; a blending_spline_surface takes a surface"),
                    ));
                }
                _ => {
                    return Err(DocumentError::new(
                        field(),
                        "only a blending_spline or blending_spline_surface takes its model from another object",
                    ));
                }
            }
        }
        Ok(())
    }

    /// Checks the ranges serde does not: at least one object, at most two lights, sizes,
    /// colours, the animation clock and the camera.
    fn check(&self) -> Result<()> {
        if self.objects.is_empty() {
            return Err(DocumentError::new("objects", "a scene needs at least one object"));
        }
        if self.lights.len() > 2 {
            return Err(DocumentError::new("lights", format!("at most 2 lights, got {}", self.lights.len())));
        }
        for (i, l) in self.lights.iter().enumerate() {
            let ok = l.direction.iter().all(|x| x.is_finite())
                && l.direction.iter().any(|&x| x != 0.0)
                && l.intensity.is_finite()
                && l.intensity >= 0.0;
            if !ok {
                return Err(DocumentError::new(
                    format!("lights[{i}]"),
                    "direction must be finite and non-zero, intensity finite and ≥ 0",
                ));
            }
        }
        let size = self.size;
        if !(1..=MAX_SIZE).contains(&size[0]) || !(1..=MAX_SIZE).contains(&size[1]) {
            return Err(DocumentError::new(
                "size",
                format!("each side must be between 1 and {MAX_SIZE} pixels, got {}×{}", size[0], size[1]),
            ));
        }
        let background = self.background;
        if background.iter().any(|c| !(0.0..=1.0).contains(c)) {
            return Err(DocumentError::new("background", format!("colours are in [0, 1], got {background:?}")));
        }
        let a = self.clock();
        if !(a.duration > 0.0 && a.duration <= 600.0 && a.fps > 0.0 && a.fps <= 100.0) {
            return Err(DocumentError::new(
                "animation",
                format!("duration must be in (0, 600] seconds and fps in (0, 100], got {} and {}", a.duration, a.fps),
            ));
        }
        if let Some(CameraDoc::LookAt { eye, target, up, fov, half_height }) = &self.camera {
            let finite = eye.iter().chain(target).chain(up).all(|x| x.is_finite());
            if !finite || eye == target || !(*fov > 1.0 && *fov < 170.0) {
                return Err(DocumentError::new(
                    "camera",
                    "eye, target and up must be finite, eye ≠ target, fov in (1, 170) degrees",
                ));
            }
            if let Some(h) = half_height
                && !(h.is_finite() && *h > 0.0)
            {
                return Err(DocumentError::new("camera.half_height", format!("must be finite and > 0, got {h}")));
            }
        }
        Ok(())
    }

    /// A scene of one shape with the default style.
    pub fn of_shape(shape: ShapeDocument) -> Self {
        SceneDocument {
            objects: vec![SceneObject {
                shape,
                style: StyleDoc::default(),
                points: Vec::new(),
                model_of: None,
                placement: None,
                instance_of: None,
                name: None,
            }],
            camera: None,
            lights: Vec::new(),
            background: white(),
            size: default_size(),
            axes: false,
            animation: None,
        }
    }

    /// The scene as a JSON document that [`SceneDocument::from_value`] reads back to an
    /// equal scene: each object's shape under `shape`, its style fields and `points` beside it.
    pub fn to_value(&self) -> Value {
        // A linked model is written as the link alone (`model_of`), not as its copy.
        let objects: Vec<Value> = self
            .objects
            .iter()
            .map(|o| {
                let mut v = o.to_value();
                if o.model_of.is_some()
                    && let Some(shape) = v.get_mut("shape").and_then(Value::as_object_mut)
                {
                    shape.remove("model");
                }
                v
            })
            .collect();
        let mut doc = serde_json::Map::new();
        doc.insert("type".into(), "scene".into());
        doc.insert("objects".into(), objects.into());
        if let Some(c) = &self.camera {
            doc.insert("camera".into(), serde_json::to_value(c).unwrap_or(Value::Null));
        }
        if !self.lights.is_empty() {
            doc.insert("lights".into(), serde_json::to_value(&self.lights).unwrap_or(Value::Null));
        }
        doc.insert("background".into(), serde_json::json!(self.background));
        doc.insert("size".into(), serde_json::json!(self.size));
        if self.axes {
            doc.insert("axes".into(), true.into());
        }
        if let Some(a) = &self.animation {
            doc.insert("animation".into(), serde_json::to_value(a).unwrap_or(Value::Null));
        }
        Value::Object(doc)
    }

    /// The animation clock: the document's, else 1 s at 20 fps.
    pub fn clock(&self) -> AnimationDoc {
        self.animation.unwrap_or_default()
    }

    /// Whether any object carries an animation.
    pub fn is_animated(&self) -> bool {
        self.objects.iter().any(|o| {
            let v = match &o.shape {
                ShapeDocument::Curve(c) => c.to_value(),
                ShapeDocument::Surface(s) => s.to_value(),
            };
            contains_key(&v, "animation")
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_gallery_scene_reads_back_from_its_own_json() {
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/scenes");
        for entry in std::fs::read_dir(dir).expect("the gallery") {
            let path = entry.expect("an entry").path();
            let text = std::fs::read_to_string(&path).expect("readable");
            let scene = SceneOrShape::from_json(&text).expect("a valid scene").into_scene();
            let again = SceneDocument::from_value(scene.to_value()).expect("its JSON parses");
            assert_eq!(again, scene, "{}", path.display());
        }
    }
}

fn contains_key(v: &Value, key: &str) -> bool {
    match v {
        Value::Object(m) => m.iter().any(|(k, x)| (k == key && !x.is_null()) || contains_key(x, key)),
        Value::Array(a) => a.iter().any(|x| contains_key(x, key)),
        _ => false,
    }
}

/// A scene or a bare shape.
#[derive(Debug, Clone, PartialEq)]
pub enum SceneOrShape {
    /// A scene document.
    Scene(SceneDocument),
    /// A shape document.
    Shape(ShapeDocument),
}

impl SceneOrShape {
    /// Parses JSON text that is either a scene or a shape.
    pub fn from_json(text: &str) -> Result<Self> {
        let value = crate::json::parse_text(text)?;
        Self::from_value(value)
    }
    /// Parses JSON text read from a file in `folder` (the current folder for standard
    /// input): as [`Self::from_json`], with the cage files of subdivision surfaces read
    /// from paths relative to `folder` ([`crate::cage_file`]).
    pub fn from_json_in(text: &str, folder: &std::path::Path) -> Result<Self> {
        let mut value = crate::json::parse_text(text)?;
        crate::cage_file::read_cage_files(&mut value, folder)?;
        Self::from_value(value)
    }
    /// A scene or shape from its JSON value.
    pub fn from_value(value: Value) -> Result<Self> {
        if value.get("type").and_then(Value::as_str) == Some("scene") {
            Ok(SceneOrShape::Scene(SceneDocument::from_value(value)?))
        } else {
            Ok(SceneOrShape::Shape(ShapeDocument::from_value(value)?))
        }
    }
    /// The scene (a shape becomes a one-object scene).
    pub fn into_scene(self) -> SceneDocument {
        match self {
            SceneOrShape::Scene(s) => s,
            SceneOrShape::Shape(s) => SceneDocument::of_shape(s),
        }
    }
}
