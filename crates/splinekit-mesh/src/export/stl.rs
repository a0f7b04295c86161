//! STL: binary (80-byte header, triangle count, 50 bytes per triangle: normal and three
//! vertices as f32, attribute count) and ASCII (`solid … facet normal … endsolid`). STL has
//! no shared vertices: each triangle carries its own corners and face normal. Both kinds
//! store 32-bit floats, so coordinates beyond ±f32::MAX are refused, and triangles whose
//! corners meet in 32-bit floats are left out (`single_precision_triangles`).

use std::io::Write;

use super::representable::{ExportError, Precision, check_mesh, one_line, single_precision_triangles};
use crate::triangle_mesh::{TriangleMesh, unit_or_zero, v3};

/// A triangle read from STL: face normal and three corners.
pub type StlTriangle = ([f32; 3], [[f32; 3]; 3]);

/// The facet normal of triangle `t`: its face normal, or for a triangle without area the
/// mean of its vertex normals.
fn facet_normal(mesh: &TriangleMesh, t: usize) -> [f64; 3] {
    let n = mesh.face_normal(t);
    if v3(n).norm() > 0.5 || mesh.normals.is_empty() {
        return n;
    }
    let corners = mesh.triangles[t].map(|i| mesh.normals[i as usize]);
    unit_or_zero(v3(corners[0]) + v3(corners[1]) + v3(corners[2]))
}

/// Writes the mesh as binary STL to `out` (give it a buffered writer).
pub fn write_stl_binary(mesh: &TriangleMesh, mut out: impl Write) -> Result<(), ExportError> {
    let mesh = &*single_precision_triangles(mesh, "STL")?;
    check_mesh(mesh, Precision::Single, "STL")?;
    let count = u32::try_from(mesh.triangles.len()).map_err(|_| ExportError::Unrepresentable {
        field: "triangles".into(),
        message: format!("{} triangles are more than binary STL can count (2³² − 1)", mesh.triangles.len()),
    })?;
    let mut header = [0u8; 80];
    let tag = b"splinekit binary STL";
    header[..tag.len()].copy_from_slice(tag);
    out.write_all(&header)?;
    out.write_all(&count.to_le_bytes())?;
    let mut record = [0u8; 50];
    for (t, tri) in mesh.triangles.iter().enumerate() {
        let values = std::iter::once(facet_normal(mesh, t)).chain(tri.iter().map(|&i| mesh.positions[i as usize]));
        for (k, v) in values.flatten().enumerate() {
            record[4 * k..4 * k + 4].copy_from_slice(&(v as f32).to_le_bytes());
        }
        out.write_all(&record)?;
    }
    out.flush()?;
    Ok(())
}

/// Writes the mesh as ASCII STL to `out` (give it a buffered writer).
pub fn write_stl_ascii(mesh: &TriangleMesh, name: &str, mut out: impl Write) -> Result<(), ExportError> {
    let mesh = &*single_precision_triangles(mesh, "STL")?;
    check_mesh(mesh, Precision::Single, "STL")?;
    let name = one_line(name);
    writeln!(out, "solid {name}")?;
    for (t, tri) in mesh.triangles.iter().enumerate() {
        let n = facet_normal(mesh, t);
        writeln!(out, "  facet normal {:e} {:e} {:e}\n    outer loop", n[0], n[1], n[2])?;
        for &i in tri {
            let p = mesh.positions[i as usize];
            writeln!(out, "      vertex {:e} {:e} {:e}", p[0], p[1], p[2])?;
        }
        out.write_all(b"    endloop\n  endfacet\n")?;
    }
    writeln!(out, "endsolid {name}")?;
    out.flush()?;
    Ok(())
}

/// Triangles of an STL file (binary or ASCII), as (face normal, three corners).
pub fn read_stl(bytes: &[u8]) -> Result<Vec<StlTriangle>, String> {
    if bytes.starts_with(b"solid") && bytes.len() >= 84 {
        let count = u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]) as usize;
        if 84 + 50 * count != bytes.len() {
            return read_ascii(std::str::from_utf8(bytes).map_err(|e| e.to_string())?);
        }
    } else if bytes.starts_with(b"solid") {
        return read_ascii(std::str::from_utf8(bytes).map_err(|e| e.to_string())?);
    }
    if bytes.len() < 84 {
        return Err(format!("{} bytes is too short for binary STL", bytes.len()));
    }
    let count = u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]) as usize;
    if bytes.len() != 84 + 50 * count {
        return Err(format!("{count} triangles need {} bytes, the file has {}", 84 + 50 * count, bytes.len()));
    }
    let f = |o: usize| f32::from_le_bytes([bytes[o], bytes[o + 1], bytes[o + 2], bytes[o + 3]]);
    Ok((0..count)
        .map(|t| {
            let o = 84 + 50 * t;
            let v = |k: usize| [f(o + 12 * k), f(o + 12 * k + 4), f(o + 12 * k + 8)];
            (v(0), [v(1), v(2), v(3)])
        })
        .collect())
}

fn read_ascii(text: &str) -> Result<Vec<StlTriangle>, String> {
    let mut out = Vec::new();
    let mut normal = [0.0; 3];
    let mut corners = Vec::new();
    for (k, line) in text.lines().enumerate() {
        let words: Vec<&str> = line.split_whitespace().collect();
        let three = |w: &[&str]| -> Result<[f32; 3], String> {
            let v: Result<Vec<f32>, _> = w.iter().map(|x| x.parse::<f32>()).collect();
            let v = v.map_err(|e| format!("line {}: {e}", k + 1))?;
            if v.len() != 3 {
                return Err(format!("line {}: expected 3 numbers", k + 1));
            }
            Ok([v[0], v[1], v[2]])
        };
        match words.first() {
            Some(&"facet") if words.get(1) == Some(&"normal") => normal = three(&words[2..])?,
            Some(&"vertex") => corners.push(three(&words[1..])?),
            Some(&"endfacet") => {
                if corners.len() != 3 {
                    return Err(format!("line {}: a facet needs 3 vertices, got {}", k + 1, corners.len()));
                }
                out.push((normal, [corners[0], corners[1], corners[2]]));
                corners.clear();
            }
            _ => {}
        }
    }
    Ok(out)
}
