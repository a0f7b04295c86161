//! glTF 2.0, as `.gltf` (JSON with the buffer embedded as a base64 data URI) or `.glb`
//! (binary container). One node and one mesh per object: triangle meshes with POSITION,
//! NORMAL and optionally TEXCOORD_0 and COLOR_0, or line strips for curves; a material per
//! object (its colour, double-sided). Animated objects carry their frames as morph targets
//! (position and normal offsets from the first frame) and an animation of the node's
//! weights that steps linearly from one frame to the next.

use serde_json::{Value, json};

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
    /// A float accessor of `n`-component elements (with min/max when `bounds`).
    fn floats(&mut self, data: &[f32], n: usize, kind: &str, bounds: bool, target: Option<u32>) -> usize {
        let bytes: Vec<u8> = data.iter().flat_map(|x| x.to_le_bytes()).collect();
        let view = self.view(&bytes, target);
        let count = data.len() / n;
        let mut a = json!({"bufferView": view, "componentType": 5126, "count": count, "type": kind});
        if bounds && count > 0 {
            let mut lo = vec![f32::INFINITY; n];
            let mut hi = vec![f32::NEG_INFINITY; n];
            for e in data.chunks_exact(n) {
                for k in 0..n {
                    lo[k] = lo[k].min(e[k]);
                    hi[k] = hi[k].max(e[k]);
                }
            }
            a["min"] = json!(lo);
            a["max"] = json!(hi);
        }
        self.accessors.push(a);
        self.accessors.len() - 1
    }
    fn indices(&mut self, data: &[u32]) -> usize {
        let bytes: Vec<u8> = data.iter().flat_map(|x| x.to_le_bytes()).collect();
        let view = self.view(&bytes, Some(34963));
        self.accessors.push(json!({"bufferView": view, "componentType": 5125, "count": data.len(), "type": "SCALAR"}));
        self.accessors.len() - 1
    }
}

fn flat3(v: &[[f64; 3]]) -> Vec<f32> {
    v.iter().flat_map(|p| p.map(|x| x as f32)).collect()
}

impl GltfScene {
    /// A scene of one still object.
    pub fn single(name: &str, geometry: GltfGeometry, color: [f32; 4]) -> Self {
        GltfScene { objects: vec![GltfObject { name: name.to_string(), geometry, color, frames: vec![] }] }
    }

    /// `.glb` bytes for `ext` = "glb", else `.gltf` text bytes.
    pub fn to_file_bytes(&self, ext: &str) -> Vec<u8> {
        if ext.eq_ignore_ascii_case("glb") { self.to_glb() } else { self.to_gltf().into_bytes() }
    }

    /// The glTF JSON document and its binary buffer.
    fn build(&self) -> (Value, Vec<u8>) {
        let mut b = Builder::default();
        let (mut meshes, mut nodes, mut materials, mut animations) = (vec![], vec![], vec![], vec![]);
        for (k, obj) in self.objects.iter().enumerate() {
            materials.push(json!({
                "name": obj.name,
                "doubleSided": true,
                "pbrMetallicRoughness": {"baseColorFactor": obj.color, "metallicFactor": 0.0, "roughnessFactor": 0.6}
            }));
            let mut prim = match &obj.geometry {
                GltfGeometry::Mesh(m) => {
                    let mut attrs = json!({"POSITION": b.floats(&flat3(&m.positions), 3, "VEC3", true, Some(34962))});
                    if m.normals.len() == m.positions.len() {
                        attrs["NORMAL"] = json!(b.floats(&flat3(&m.normals), 3, "VEC3", false, Some(34962)));
                    }
                    if m.uvs.len() == m.positions.len() {
                        let uv: Vec<f32> = m.uvs.iter().flat_map(|t| [t[0] as f32, 1.0 - t[1] as f32]).collect();
                        attrs["TEXCOORD_0"] = json!(b.floats(&uv, 2, "VEC2", false, Some(34962)));
                    }
                    if m.colors.len() == m.positions.len() {
                        let c: Vec<f32> = m.colors.iter().flatten().copied().collect();
                        attrs["COLOR_0"] = json!(b.floats(&c, 4, "VEC4", false, Some(34962)));
                    }
                    let flat: Vec<u32> = m.triangles.iter().flatten().copied().collect();
                    json!({"attributes": attrs, "indices": b.indices(&flat), "mode": 4, "material": k})
                }
                GltfGeometry::LineStrip(points) => {
                    json!({"attributes": {"POSITION": b.floats(&flat3(points), 3, "VEC3", true, Some(34962))}, "mode": 3, "material": k})
                }
            };
            let mut mesh = json!({"name": obj.name});
            if obj.frames.len() > 1 {
                let (_, base_p, base_n) = &obj.frames[0];
                let mut targets = Vec::new();
                for (_, p, n) in &obj.frames {
                    let dp: Vec<[f64; 3]> =
                        p.iter().zip(base_p).map(|(a, c)| [a[0] - c[0], a[1] - c[1], a[2] - c[2]]).collect();
                    let mut t = json!({"POSITION": b.floats(&flat3(&dp), 3, "VEC3", true, None)});
                    if n.len() == p.len() && base_n.len() == p.len() {
                        let dn: Vec<[f64; 3]> =
                            n.iter().zip(base_n).map(|(a, c)| [a[0] - c[0], a[1] - c[1], a[2] - c[2]]).collect();
                        t["NORMAL"] = json!(b.floats(&flat3(&dn), 3, "VEC3", false, None));
                    }
                    targets.push(t);
                }
                prim["targets"] = json!(targets);
                let f = obj.frames.len();
                mesh["weights"] = json!(vec![0.0; f]);
                let times: Vec<f32> = obj.frames.iter().map(|(t, _, _)| *t).collect();
                let mut weights = vec![0.0f32; f * f];
                for i in 0..f {
                    weights[i * f + i] = 1.0;
                }
                let input = b.floats(&times, 1, "SCALAR", true, None);
                let output = b.floats(&weights, 1, "SCALAR", false, None);
                animations.push(json!({
                    "name": obj.name,
                    "samplers": [{"input": input, "output": output, "interpolation": "LINEAR"}],
                    "channels": [{"sampler": 0, "target": {"node": k, "path": "weights"}}]
                }));
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
        (doc, b.bin)
    }

    /// The scene as a `.gltf` file (buffer embedded as a data URI).
    pub fn to_gltf(&self) -> String {
        let (mut doc, bin) = self.build();
        doc["buffers"][0]["uri"] = json!(format!("data:application/octet-stream;base64,{}", base64(&bin)));
        serde_json::to_string(&doc).expect("JSON serialises")
    }

    /// The scene as a `.glb` file.
    pub fn to_glb(&self) -> Vec<u8> {
        let (doc, mut bin) = self.build();
        let mut json = serde_json::to_vec(&doc).expect("JSON serialises");
        while json.len() % 4 != 0 {
            json.push(b' ');
        }
        while bin.len() % 4 != 0 {
            bin.push(0);
        }
        let total = 12 + 8 + json.len() + 8 + bin.len();
        let mut out = Vec::with_capacity(total);
        out.extend_from_slice(b"glTF");
        out.extend_from_slice(&2u32.to_le_bytes());
        out.extend_from_slice(&(total as u32).to_le_bytes());
        out.extend_from_slice(&(json.len() as u32).to_le_bytes());
        out.extend_from_slice(b"JSON");
        out.extend_from_slice(&json);
        out.extend_from_slice(&(bin.len() as u32).to_le_bytes());
        out.extend_from_slice(b"BIN\0");
        out.extend_from_slice(&bin);
        out
    }
}

/// Standard base64 with padding.
fn base64(bytes: &[u8]) -> String {
    const TABLE: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut s = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [chunk[0], *chunk.get(1).unwrap_or(&0), *chunk.get(2).unwrap_or(&0)];
        let n = (b[0] as u32) << 16 | (b[1] as u32) << 8 | b[2] as u32;
        for k in 0..4 {
            if k <= chunk.len() {
                s.push(TABLE[(n >> (18 - 6 * k) & 63) as usize] as char);
            } else {
                s.push('=');
            }
        }
    }
    s
}

#[cfg(test)]
mod tests {
    #[test]
    fn base64_matches_the_rfc_examples() {
        for (plain, enc) in [("", ""), ("f", "Zg=="), ("fo", "Zm8="), ("foo", "Zm9v"), ("foobar", "Zm9vYmFy")] {
            assert_eq!(super::base64(plain.as_bytes()), enc);
        }
    }
}
