//! Wavefront OBJ: `v x y z`, `vt u v`, `vn x y z`, faces `f a/b/c` (1-based), polylines `l`.

use std::io::Write;

use super::representable::{ExportError, Precision, check_mesh, check_vectors, one_line};
use crate::triangle_mesh::TriangleMesh;

/// Writes the mesh as OBJ text (one object named `name`) to `out` (give it a buffered
/// writer); refuses non-finite numbers before writing anything.
pub fn write_obj(mesh: &TriangleMesh, name: &str, mut out: impl Write) -> Result<(), ExportError> {
    check_mesh(mesh, Precision::Double, "OBJ")?;
    writeln!(out, "# splinekit\no {}", one_line(name))?;
    for p in &mesh.positions {
        writeln!(out, "v {} {} {}", p[0], p[1], p[2])?;
    }
    for t in &mesh.uvs {
        writeln!(out, "vt {} {}", t[0], t[1])?;
    }
    for n in &mesh.normals {
        writeln!(out, "vn {} {} {}", n[0], n[1], n[2])?;
    }
    let (has_uv, has_n) = (!mesh.uvs.is_empty(), !mesh.normals.is_empty());
    for t in &mesh.triangles {
        out.write_all(b"f")?;
        for &i in t {
            let i = i + 1;
            match (has_uv, has_n) {
                (true, true) => write!(out, " {i}/{i}/{i}"),
                (false, true) => write!(out, " {i}//{i}"),
                (true, false) => write!(out, " {i}/{i}"),
                (false, false) => write!(out, " {i}"),
            }?;
        }
        out.write_all(b"\n")?;
    }
    out.flush()?;
    Ok(())
}

/// Writes a polyline as OBJ text: its vertices and one `l` element (closed polylines repeat
/// the first index at the end).
pub fn write_obj_polyline(
    points: &[[f64; 3]],
    closed: bool,
    name: &str,
    mut out: impl Write,
) -> Result<(), ExportError> {
    check_vectors(points, Precision::Double, "OBJ", "points")?;
    writeln!(out, "# splinekit\no {}", one_line(name))?;
    for p in points {
        writeln!(out, "v {} {} {}", p[0], p[1], p[2])?;
    }
    out.write_all(b"l")?;
    for i in 1..=points.len() {
        write!(out, " {i}")?;
    }
    if closed && !points.is_empty() {
        out.write_all(b" 1")?;
    }
    out.write_all(b"\n")?;
    out.flush()?;
    Ok(())
}

/// One object of an OBJ file of several: its triangles (with their normals where the mesh
/// has them) and its polylines, each a list of points and whether it closes.
#[derive(Debug, Clone, Copy)]
pub struct ObjObject<'a> {
    /// The object's name (`o` and `g`); whitespace and control characters become `_`.
    pub name: &'a str,
    /// Its triangles.
    pub mesh: &'a TriangleMesh,
    /// Its polylines (`l`).
    pub lines: &'a [(Vec<[f64; 3]>, bool)],
}

/// Writes several objects as one OBJ text: for each an `o` and a `g` line with its name,
/// its vertices and normals, its triangles (`f v//vn`, or `f v` without normals) and its
/// polylines (`l`, a closed one repeating its first vertex). Indices count over the whole
/// file. Refuses non-finite numbers before writing anything.
pub fn write_obj_objects(objects: &[ObjObject<'_>], mut out: impl Write) -> Result<(), ExportError> {
    for o in objects {
        check_mesh(o.mesh, Precision::Double, "OBJ")?;
        for (points, _) in o.lines {
            check_vectors(points, Precision::Double, "OBJ", "points")?;
        }
    }
    out.write_all(b"# splinekit\n")?;
    let (mut vertices, mut normals) = (0usize, 0usize);
    for o in objects {
        let name = one_line(o.name).replace(char::is_whitespace, "_");
        writeln!(out, "o {name}\ng {name}")?;
        for p in o.mesh.positions.iter().chain(o.lines.iter().flat_map(|(points, _)| points)) {
            writeln!(out, "v {} {} {}", p[0], p[1], p[2])?;
        }
        for n in &o.mesh.normals {
            writeln!(out, "vn {} {} {}", n[0], n[1], n[2])?;
        }
        let has_n = !o.mesh.normals.is_empty();
        for t in &o.mesh.triangles {
            out.write_all(b"f")?;
            for &i in t {
                let (v, n) = (vertices + i as usize + 1, normals + i as usize + 1);
                if has_n { write!(out, " {v}//{n}") } else { write!(out, " {v}") }?;
            }
            out.write_all(b"\n")?;
        }
        let mut first = vertices + o.mesh.positions.len() + 1;
        for (points, closed) in o.lines {
            if points.is_empty() {
                continue;
            }
            out.write_all(b"l")?;
            for i in first..first + points.len() {
                write!(out, " {i}")?;
            }
            if *closed {
                write!(out, " {first}")?;
            }
            out.write_all(b"\n")?;
            first += points.len();
        }
        vertices = first - 1;
        normals += o.mesh.normals.len();
    }
    out.flush()?;
    Ok(())
}

/// Reads the vertices, normals, texture coordinates and triangles of an OBJ file written by
/// [`write_obj`] (faces with one index triple per corner, positions and attributes sharing
/// indices). Errors name the line.
pub fn read_obj(text: &str) -> Result<TriangleMesh, String> {
    let mut mesh = TriangleMesh::default();
    let nums = |rest: &str, n: usize, line: usize| -> Result<Vec<f64>, String> {
        let v: Result<Vec<f64>, _> = rest.split_whitespace().map(str::parse).collect();
        let v = v.map_err(|e| format!("line {line}: {e}"))?;
        if v.len() != n {
            return Err(format!("line {line}: expected {n} numbers, got {}", v.len()));
        }
        Ok(v)
    };
    for (k, line) in text.lines().enumerate() {
        let line_no = k + 1;
        let (tag, rest) = line.split_once(' ').unwrap_or((line, ""));
        match tag {
            "v" => {
                let v = nums(rest, 3, line_no)?;
                mesh.positions.push([v[0], v[1], v[2]]);
            }
            "vn" => {
                let v = nums(rest, 3, line_no)?;
                mesh.normals.push([v[0], v[1], v[2]]);
            }
            "vt" => {
                let v = nums(rest, 2, line_no)?;
                mesh.uvs.push([v[0], v[1]]);
            }
            "f" => {
                let idx: Result<Vec<u32>, String> = rest
                    .split_whitespace()
                    .map(|c| {
                        let first = c.split('/').next().unwrap_or("");
                        let i: u32 = first.parse().map_err(|e| format!("line {line_no}: {e}"))?;
                        if i == 0 {
                            return Err(format!("line {line_no}: indices start at 1"));
                        }
                        Ok(i - 1)
                    })
                    .collect();
                let idx = idx?;
                if idx.len() != 3 {
                    return Err(format!("line {line_no}: expected a triangle, got {} corners", idx.len()));
                }
                mesh.triangles.push([idx[0], idx[1], idx[2]]);
            }
            _ => {}
        }
    }
    let n = mesh.positions.len() as u32;
    if let Some(t) = mesh.triangles.iter().find(|t| t.iter().any(|&i| i >= n)) {
        return Err(format!("face {t:?} refers past the {n} vertices"));
    }
    Ok(mesh)
}
