//! PLY (ASCII 1.0): vertices with `x y z`, `nx ny nz` and `s t` when present, RGBA colours
//! as `red green blue alpha` bytes when present, and triangular faces.

use std::io::Write;

use super::representable::{ExportError, Precision, check_mesh};
use crate::triangle_mesh::TriangleMesh;

/// Writes the mesh as ASCII PLY to `out` (give it a buffered writer); refuses non-finite
/// numbers before writing anything.
pub fn write_ply(mesh: &TriangleMesh, out: impl Write) -> Result<(), ExportError> {
    write_ply_with_edges(mesh, &[], out)
}

/// [`write_ply`] with `edges` (pairs of vertex indices: the segments of polylines) as an
/// `edge` element (`vertex1 vertex2`) after the faces, when there are any.
pub fn write_ply_with_edges(mesh: &TriangleMesh, edges: &[[u32; 2]], mut out: impl Write) -> Result<(), ExportError> {
    check_mesh(mesh, Precision::Double, "PLY")?;
    let n = mesh.positions.len();
    if let Some((k, e)) = edges.iter().enumerate().find(|(_, e)| e.iter().any(|&i| i as usize >= n)) {
        return Err(ExportError::Unrepresentable {
            field: format!("edges[{k}]"),
            message: format!("{e:?} refers past the {n} vertices"),
        });
    }
    let (has_n, has_uv, has_c) = (!mesh.normals.is_empty(), !mesh.uvs.is_empty(), !mesh.colors.is_empty());
    out.write_all(b"ply\nformat ascii 1.0\ncomment splinekit\n")?;
    writeln!(out, "element vertex {}", mesh.positions.len())?;
    out.write_all(b"property double x\nproperty double y\nproperty double z\n")?;
    if has_n {
        out.write_all(b"property double nx\nproperty double ny\nproperty double nz\n")?;
    }
    if has_uv {
        out.write_all(b"property double s\nproperty double t\n")?;
    }
    if has_c {
        out.write_all(b"property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n")?;
    }
    writeln!(out, "element face {}", mesh.triangles.len())?;
    out.write_all(b"property list uchar uint vertex_indices\n")?;
    if !edges.is_empty() {
        writeln!(out, "element edge {}", edges.len())?;
        out.write_all(b"property uint vertex1\nproperty uint vertex2\n")?;
    }
    out.write_all(b"end_header\n")?;
    for i in 0..mesh.positions.len() {
        let p = mesh.positions[i];
        write!(out, "{} {} {}", p[0], p[1], p[2])?;
        if has_n {
            let n = mesh.normals[i];
            write!(out, " {} {} {}", n[0], n[1], n[2])?;
        }
        if has_uv {
            write!(out, " {} {}", mesh.uvs[i][0], mesh.uvs[i][1])?;
        }
        if has_c {
            let c = mesh.colors[i].map(|x| (x.clamp(0.0, 1.0) * 255.0).round() as u8);
            write!(out, " {} {} {} {}", c[0], c[1], c[2], c[3])?;
        }
        out.write_all(b"\n")?;
    }
    for t in &mesh.triangles {
        writeln!(out, "3 {} {} {}", t[0], t[1], t[2])?;
    }
    for e in edges {
        writeln!(out, "{} {}", e[0], e[1])?;
    }
    out.flush()?;
    Ok(())
}

/// Reads an ASCII PLY written by [`write_ply`] (positions, normals, s t, triangles).
pub fn read_ply(text: &str) -> Result<TriangleMesh, String> {
    let mut lines = text.lines();
    if lines.next() != Some("ply") {
        return Err("not a PLY file".into());
    }
    let (mut nv, mut nf, mut props) = (0usize, 0usize, Vec::new());
    let mut in_vertex = false;
    for line in lines.by_ref() {
        let w: Vec<&str> = line.split_whitespace().collect();
        match w.as_slice() {
            ["format", f, _] if *f != "ascii" => return Err(format!("only ASCII PLY is read, got {f}")),
            ["element", "vertex", n] => {
                nv = n.parse().map_err(|e| format!("vertex count: {e}"))?;
                in_vertex = true;
            }
            ["element", "face", n] => {
                nf = n.parse().map_err(|e| format!("face count: {e}"))?;
                in_vertex = false;
            }
            ["property", _, name] if in_vertex => props.push(name.to_string()),
            ["end_header"] => break,
            _ => {}
        }
    }
    let pos = |name: &str| props.iter().position(|p| p == name);
    let mut mesh = TriangleMesh::default();
    for k in 0..nv {
        let line = lines.next().ok_or_else(|| format!("vertex {k} is missing"))?;
        let v: Result<Vec<f64>, _> = line.split_whitespace().map(str::parse).collect();
        let v = v.map_err(|e| format!("vertex {k}: {e}"))?;
        if v.len() != props.len() {
            return Err(format!("vertex {k}: expected {} values, got {}", props.len(), v.len()));
        }
        let get = |n: &str| pos(n).map(|i| v[i]);
        mesh.positions.push([get("x").unwrap_or(0.0), get("y").unwrap_or(0.0), get("z").unwrap_or(0.0)]);
        if let (Some(x), Some(y), Some(z)) = (get("nx"), get("ny"), get("nz")) {
            mesh.normals.push([x, y, z]);
        }
        if let (Some(s), Some(t)) = (get("s"), get("t")) {
            mesh.uvs.push([s, t]);
        }
    }
    for k in 0..nf {
        let line = lines.next().ok_or_else(|| format!("face {k} is missing"))?;
        let v: Result<Vec<u32>, _> = line.split_whitespace().map(str::parse).collect();
        let v = v.map_err(|e| format!("face {k}: {e}"))?;
        if v.len() != 4 || v[0] != 3 || v[1..].iter().any(|&i| i as usize >= nv) {
            return Err(format!("face {k}: expected a triangle of valid indices, got {v:?}"));
        }
        mesh.triangles.push([v[1], v[2], v[3]]);
    }
    Ok(mesh)
}
