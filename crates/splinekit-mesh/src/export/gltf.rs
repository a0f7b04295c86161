//! glTF 2.0, as `.gltf` (JSON with the buffer embedded as a base64 data URI) or `.glb`
//! (binary container). One node and one mesh per object: triangle meshes with POSITION,
//! NORMAL and optionally TEXCOORD_0 and COLOR_0, or line strips for curves; a material per
//! object (its colour, double-sided). Animated objects carry their frames as morph targets
//! (position and normal offsets from the first frame) and an animation of the node's
//! weights that steps linearly from one frame to the next.

use serde_json::{Value, json};

use super::base64::base64;
use super::format::Format;
use super::representable::{ExportError, Precision, check_mesh, check_value, single_precision_triangles};
use crate::triangle_mesh::TriangleMesh;

/// An animation frame: time in seconds, vertex positions, vertex normals.
pub type Frame = (f32, Vec<[f64; 3]>, Vec<[f64; 3]>);

/// One object of a glTF scene.
#[derive(Debug, Clone)]
pub struct GltfObject {
    /// Node and mesh name.
    pub name: String,
    /// Its geometry.
    pub geometry: GltfGeometry,
    /// Base colour, linear RGBA.
    pub color: [f32; 4],
    /// Animation frames: (time in seconds, positions, normals), positions and normals
    /// matching the geometry's vertices. Empty for a still object.
    pub frames: Vec<Frame>,
}

/// Geometry of an object.
#[derive(Debug, Clone)]
pub enum GltfGeometry {
    /// A triangle mesh.
    Mesh(TriangleMesh),
    /// A polyline (closed ones repeat their first point at the end).
    LineStrip(Vec<[f64; 3]>),
    /// A polyline with a linear RGBA colour per point (`COLOR_0`, a colour map), one per
    /// point of the strip.
    ColoredLineStrip(Vec<[f64; 3]>, Vec<[f32; 4]>),
}

/// A glTF scene of several objects.
#[derive(Debug, Clone, Default)]
pub struct GltfScene {
    /// The objects, one node each.
    pub objects: Vec<GltfObject>,
}

#[derive(Default)]
struct Builder {
    bin: Vec<u8>,
    views: Vec<Value>,
    accessors: Vec<Value>,
}

/// What an accessor holds, for error messages: `objects[0] ("torus") POSITION`.
struct Named<'a> {
    object: usize,
    name: &'a str,
    what: &'a str,
}

impl std::fmt::Display for Named<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "objects[{}] ({:?}) {}", self.object, self.name, self.what)
    }
}

impl Builder {
    fn view(&mut self, bytes: &[u8], target: Option<u32>) -> usize {
        while self.bin.len() % 4 != 0 {
            self.bin.push(0);
        }
        let mut v = json!({"buffer": 0, "byteOffset": self.bin.len(), "byteLength": bytes.len()});
        if let Some(t) = target {
            v["target"] = json!(t);
        }
        self.bin.extend_from_slice(bytes);
        self.views.push(v);
        self.views.len() - 1
    }
    /// A float accessor of `N`-component elements (with min/max when `bounds`), refusing
    /// values that are not finite as 32-bit floats.
    fn floats<const N: usize>(
        &mut self,
        data: &[[f64; N]],
        kind: &str,
        bounds: bool,
        target: Option<u32>,
        named: Named<'_>,
    ) -> Result<usize, ExportError> {
        let mut bytes = Vec::with_capacity(4 * N * data.len());
        let mut lo = [f32::INFINITY; N];
        let mut hi = [f32::NEG_INFINITY; N];
        for (i, e) in data.iter().enumerate() {
            for k in 0..N {
                check_value(e[k], Precision::Single, "glTF", || format!("{named}[{i}][{k}]"))?;
                let x = e[k] as f32;
                bytes.extend_from_slice(&x.to_le_bytes());
                lo[k] = lo[k].min(x);
                hi[k] = hi[k].max(x);
            }
        }
        let view = self.view(&bytes, target);
        let mut a = json!({"bufferView": view, "componentType": 5126, "count": data.len(), "type": kind});
        if bounds && !data.is_empty() {
            a["min"] = json!(lo.to_vec());
            a["max"] = json!(hi.to_vec());
        }
        self.accessors.push(a);
        Ok(self.accessors.len() - 1)
    }
    fn indices(&mut self, data: &[u32]) -> usize {
        let bytes: Vec<u8> = data.iter().flat_map(|x| x.to_le_bytes()).collect();
        let view = self.view(&bytes, Some(34963));
        self.accessors.push(json!({"bufferView": view, "componentType": 5125, "count": data.len(), "type": "SCALAR"}));
        self.accessors.len() - 1
    }
}

/// glTF requires unit NORMALs: refuses one whose length, in f32, is off by more than 10⁻⁴.
fn check_unit_normals(normals: &[[f64; 3]], named: &Named<'_>) -> Result<(), ExportError> {
    for (i, n) in normals.iter().enumerate() {
        let len = n.iter().map(|&x| (x as f32 as f64).powi(2)).sum::<f64>().sqrt();
        let unit = (len - 1.0).abs() <= 1e-4;
        if !unit {
            return Err(ExportError::Unrepresentable {
                field: format!("{named}[{i}]"),
                message: format!("has length {len}, but glTF normals must have unit length"),
            });
        }
    }
    Ok(())
}

/// The component-wise difference a − b of two equally long lists.
fn offsets(a: &[[f64; 3]], b: &[[f64; 3]]) -> Vec<[f64; 3]> {
    a.iter().zip(b).map(|(p, q)| [p[0] - q[0], p[1] - q[1], p[2] - q[2]]).collect()
}

impl GltfScene {
    /// A scene of one still object.
    pub fn single(name: &str, geometry: GltfGeometry, color: [f32; 4]) -> Self {
        GltfScene { objects: vec![GltfObject { name: name.to_string(), geometry, color, frames: vec![] }] }
    }

    /// `.glb` bytes for [`Format::Glb`], else `.gltf` text bytes.
    pub fn to_format_bytes(&self, format: Format) -> Result<Vec<u8>, ExportError> {
        if format == Format::Glb { self.to_glb() } else { Ok(self.to_gltf()?.into_bytes()) }
    }

    /// The primitive of one object's geometry.
    fn primitive(b: &mut Builder, k: usize, obj: &GltfObject) -> Result<Value, ExportError> {
        let named = |what| Named { object: k, name: &obj.name, what };
        Ok(match &obj.geometry {
            GltfGeometry::Mesh(m) => {
                let m = &*single_precision_triangles(m, "glTF")
                    .and_then(|m| check_mesh(&m, Precision::Single, "glTF").map(|()| m))
                    .map_err(|e| match e {
                        ExportError::Unrepresentable { field, message } => {
                            ExportError::Unrepresentable { field: format!("{} {field}", named("mesh")), message }
                        }
                        other => other,
                    })?;
                let mut attrs =
                    json!({"POSITION": b.floats(&m.positions, "VEC3", true, Some(34962), named("POSITION"))?});
                if m.normals.len() == m.positions.len() {
                    check_unit_normals(&m.normals, &named("NORMAL"))?;
                    attrs["NORMAL"] = json!(b.floats(&m.normals, "VEC3", false, Some(34962), named("NORMAL"))?);
                }
                if m.uvs.len() == m.positions.len() {
                    let uv: Vec<[f64; 2]> = m.uvs.iter().map(|t| [t[0], 1.0 - t[1]]).collect();
                    attrs["TEXCOORD_0"] = json!(b.floats(&uv, "VEC2", false, Some(34962), named("TEXCOORD_0"))?);
                }
                if m.colors.len() == m.positions.len() {
                    let c: Vec<[f64; 4]> = m.colors.iter().map(|c| c.map(f64::from)).collect();
                    attrs["COLOR_0"] = json!(b.floats(&c, "VEC4", false, Some(34962), named("COLOR_0"))?);
                }
                let flat: Vec<u32> = m.triangles.iter().flatten().copied().collect();
                json!({"attributes": attrs, "indices": b.indices(&flat), "mode": 4, "material": k})
            }
            GltfGeometry::LineStrip(points) => {
                let position = b.floats(points, "VEC3", true, Some(34962), named("POSITION"))?;
                json!({"attributes": {"POSITION": position}, "mode": 3, "material": k})
            }
            GltfGeometry::ColoredLineStrip(points, colors) => {
                let position = b.floats(points, "VEC3", true, Some(34962), named("POSITION"))?;
                let mut attrs = json!({"POSITION": position});
                if colors.len() == points.len() {
                    let c: Vec<[f64; 4]> = colors.iter().map(|c| c.map(f64::from)).collect();
                    attrs["COLOR_0"] = json!(b.floats(&c, "VEC4", false, Some(34962), named("COLOR_0"))?);
                }
                json!({"attributes": attrs, "mode": 3, "material": k})
            }
        })
    }

    /// The morph targets of an animated object and the animation of its weights.
    fn morph_targets(b: &mut Builder, k: usize, obj: &GltfObject) -> Result<(Vec<Value>, Value), ExportError> {
        let (_, base_p, base_n) = &obj.frames[0];
        let mut targets = Vec::new();
        for (f, (time, p, n)) in obj.frames.iter().enumerate() {
            check_value(*time as f64, Precision::Single, "glTF", || format!("objects[{k}] frames[{f}] time"))?;
            let what = format!("frames[{f}] POSITION offset");
            let named = Named { object: k, name: &obj.name, what: &what };
            let mut t = json!({"POSITION": b.floats(&offsets(p, base_p), "VEC3", true, Some(34962), named)?});
            if n.len() == p.len() && base_n.len() == p.len() {
                let what = format!("frames[{f}] NORMAL offset");
                let named = Named { object: k, name: &obj.name, what: &what };
                t["NORMAL"] = json!(b.floats(&offsets(n, base_n), "VEC3", false, Some(34962), named)?);
            }
            targets.push(t);
        }
        let f = obj.frames.len();
        let times: Vec<[f64; 1]> = obj.frames.iter().map(|(t, _, _)| [*t as f64]).collect();
        let weights: Vec<[f64; 1]> = (0..f * f).map(|i| [if i / f == i % f { 1.0 } else { 0.0 }]).collect();
        let input =
            b.floats(&times, "SCALAR", true, None, Named { object: k, name: &obj.name, what: "frame times" })?;
        let output =
            b.floats(&weights, "SCALAR", false, None, Named { object: k, name: &obj.name, what: "weights" })?;
        let animation = json!({
            "name": obj.name,
            "samplers": [{"input": input, "output": output, "interpolation": "LINEAR"}],
            "channels": [{"sampler": 0, "target": {"node": k, "path": "weights"}}]
        });
        Ok((targets, animation))
    }

    /// The glTF JSON document and its binary buffer.
    fn build(&self) -> Result<(Value, Vec<u8>), ExportError> {
        let mut b = Builder::default();
        let (mut meshes, mut nodes, mut materials, mut animations) = (vec![], vec![], vec![], vec![]);
        for (k, obj) in self.objects.iter().enumerate() {
            for (c, &x) in obj.color.iter().enumerate() {
                check_value(x as f64, Precision::Single, "glTF", || format!("objects[{k}] color[{c}]"))?;
            }
            materials.push(json!({
                "name": obj.name,
                "doubleSided": true,
                "pbrMetallicRoughness": {"baseColorFactor": obj.color, "metallicFactor": 0.0, "roughnessFactor": 0.6}
            }));
            let mut prim = Self::primitive(&mut b, k, obj)?;
            let mut mesh = json!({"name": obj.name});
            if obj.frames.len() > 1 {
                let (targets, animation) = Self::morph_targets(&mut b, k, obj)?;
                prim["targets"] = json!(targets);
                mesh["weights"] = json!(vec![0.0; obj.frames.len()]);
                animations.push(animation);
            }
            mesh["primitives"] = json!([prim]);
            meshes.push(mesh);
            nodes.push(json!({"name": obj.name, "mesh": k}));
        }
        let mut doc = json!({
            "asset": {"version": "2.0", "generator": "splinekit"},
            "scene": 0,
            "scenes": [{"nodes": (0..self.objects.len()).collect::<Vec<_>>()}],
            "nodes": nodes,
            "meshes": meshes,
            "materials": materials,
            "accessors": b.accessors,
            "bufferViews": b.views,
            "buffers": [{"byteLength": b.bin.len()}],
        });
        if !animations.is_empty() {
            doc["animations"] = json!(animations);
        }
        Ok((doc, b.bin))
    }

    /// The scene as a `.gltf` file (buffer embedded as a data URI).
    pub fn to_gltf(&self) -> Result<String, ExportError> {
        let (mut doc, bin) = self.build()?;
        doc["buffers"][0]["uri"] = json!(format!("data:application/octet-stream;base64,{}", base64(&bin)));
        Ok(serde_json::to_string(&doc).expect("JSON of finite numbers serialises"))
    }

    /// The scene as a `.glb` file.
    pub fn to_glb(&self) -> Result<Vec<u8>, ExportError> {
        let (doc, mut bin) = self.build()?;
        let mut json = serde_json::to_vec(&doc).expect("JSON of finite numbers serialises");
        while json.len() % 4 != 0 {
            json.push(b' ');
        }
        while bin.len() % 4 != 0 {
            bin.push(0);
        }
        let total = 12 + 8 + json.len() + 8 + bin.len();
        let too_big = |_| ExportError::Unrepresentable {
            field: "glb".into(),
            message: format!("{total} bytes are more than a .glb file can hold (2³² − 1)"),
        };
        let total32 = u32::try_from(total).map_err(too_big)?;
        let mut out = Vec::with_capacity(total);
        out.extend_from_slice(b"glTF");
        out.extend_from_slice(&2u32.to_le_bytes());
        out.extend_from_slice(&total32.to_le_bytes());
        out.extend_from_slice(&(json.len() as u32).to_le_bytes());
        out.extend_from_slice(b"JSON");
        out.extend_from_slice(&json);
        out.extend_from_slice(&(bin.len() as u32).to_le_bytes());
        out.extend_from_slice(b"BIN\0");
        out.extend_from_slice(&bin);
        Ok(out)
    }
}
