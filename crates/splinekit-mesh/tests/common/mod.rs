//! Helpers shared by the integration tests: writer output in memory, and glTF read back
//! with the `gltf` crate.

#![allow(dead_code)]

use splinekit_mesh::export::ExportError;

/// What a writer puts into a file.
pub fn bytes(write: impl FnOnce(&mut Vec<u8>) -> Result<(), ExportError>) -> Vec<u8> {
    let mut out = Vec::new();
    write(&mut out).unwrap();
    out
}

/// What a text writer puts into a file.
pub fn text(write: impl FnOnce(&mut Vec<u8>) -> Result<(), ExportError>) -> String {
    String::from_utf8(bytes(write)).unwrap()
}

/// Standard base64 decoding (padding ignored).
pub fn base64_decode(s: &str) -> Vec<u8> {
    let val = |c: u8| -> u32 {
        match c {
            b'A'..=b'Z' => (c - b'A') as u32,
            b'a'..=b'z' => (c - b'a' + 26) as u32,
            b'0'..=b'9' => (c - b'0' + 52) as u32,
            b'+' => 62,
            _ => 63,
        }
    };
    let bytes: Vec<u8> = s.bytes().filter(|&c| c != b'=').collect();
    let mut out = Vec::new();
    for chunk in bytes.chunks(4) {
        let n = chunk.iter().enumerate().fold(0u32, |acc, (k, &c)| acc | val(c) << (18 - 6 * k));
        for k in 0..chunk.len() - 1 {
            out.push((n >> (16 - 8 * k)) as u8);
        }
    }
    out
}

/// A triangle mesh as a glTF file holds it.
pub struct GltfMesh {
    /// POSITION.
    pub positions: Vec<[f32; 3]>,
    /// NORMAL (empty if absent).
    pub normals: Vec<[f32; 3]>,
    /// Triangles.
    pub triangles: Vec<[u32; 3]>,
}

/// The triangle meshes of a .gltf (embedded buffer) or .glb file, read by the `gltf` crate.
pub fn gltf_meshes(file: &[u8]) -> Vec<GltfMesh> {
    let doc = gltf::Gltf::from_slice(file).unwrap();
    let blob = match doc.blob.clone() {
        Some(b) => b,
        None => {
            let buffer = doc.buffers().next().unwrap();
            let gltf::buffer::Source::Uri(uri) = buffer.source() else { panic!("embedded buffer") };
            base64_decode(uri.split_once(',').unwrap().1)
        }
    };
    let mut out = Vec::new();
    for mesh in doc.meshes() {
        for prim in mesh.primitives().filter(|p| p.mode() == gltf::mesh::Mode::Triangles) {
            let reader = prim.reader(|_| Some(&blob[..]));
            let idx: Vec<u32> = reader.read_indices().unwrap().into_u32().collect();
            out.push(GltfMesh {
                positions: reader.read_positions().unwrap().collect(),
                normals: reader.read_normals().map(|n| n.collect()).unwrap_or_default(),
                triangles: idx.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect(),
            });
        }
    }
    out
}
