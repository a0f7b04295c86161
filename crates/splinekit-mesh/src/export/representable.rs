//! Which numbers a file format can hold, and the error of the writers.
//!
//! Text formats written in double precision (OBJ, PLY with `double` properties, SVG) need
//! finite numbers; formats that store 32-bit floats (binary and ASCII STL, glTF) also need
//! every number to stay finite once rounded to f32, i.e. |x| ≤ f32::MAX ≈ 3.4028235e38
//! (anything larger rounds to infinity).

use std::fmt;

/// Why a writer refused or failed.
#[derive(Debug)]
pub enum ExportError {
    /// A value the format cannot hold.
    Unrepresentable {
        /// What it is, e.g. `positions[12][1]`.
        field: String,
        /// Why, with the number and the format.
        message: String,
    },
    /// Writing the output failed.
    Io(std::io::Error),
}

impl fmt::Display for ExportError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ExportError::Unrepresentable { field, message } => write!(f, "{field}: {message}"),
            ExportError::Io(e) => write!(f, "cannot write: {e}"),
        }
    }
}

impl std::error::Error for ExportError {}

impl From<std::io::Error> for ExportError {
    fn from(e: std::io::Error) -> Self {
        ExportError::Io(e)
    }
}

/// How a format stores its numbers.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Precision {
    /// 64-bit floats (or decimal text read as such).
    Double,
    /// 32-bit floats.
    Single,
}

/// Checks one number; `field` names it in the error, `format` the file format.
pub fn check_value(
    value: f64,
    precision: Precision,
    format: &str,
    field: impl FnOnce() -> String,
) -> Result<(), ExportError> {
    let fits = match precision {
        Precision::Double => value.is_finite(),
        Precision::Single => value.is_finite() && value.abs() <= f32::MAX as f64,
    };
    if fits {
        return Ok(());
    }
    let message = if !value.is_finite() {
        format!("{value} is not a finite number, which {format} needs")
    } else {
        format!("{value:e} is beyond the largest 32-bit float ({:e}) that {format} stores", f32::MAX)
    };
    Err(ExportError::Unrepresentable { field: field(), message })
}

/// Checks every coordinate of a list of vectors named `field` (`field[i][k]` in errors).
pub fn check_vectors<const N: usize>(
    vectors: &[[f64; N]],
    precision: Precision,
    format: &str,
    field: &str,
) -> Result<(), ExportError> {
    for (i, v) in vectors.iter().enumerate() {
        for (k, &x) in v.iter().enumerate() {
            check_value(x, precision, format, || format!("{field}[{i}][{k}]"))?;
        }
    }
    Ok(())
}

/// Checks the positions, normals, (u, v) and colours of a mesh, and that its attributes
/// and triangles refer to its vertices.
pub fn check_mesh(mesh: &crate::TriangleMesh, precision: Precision, format: &str) -> Result<(), ExportError> {
    let n = mesh.positions.len();
    let unmatched = |field: &str, len: usize| ExportError::Unrepresentable {
        field: field.to_string(),
        message: format!("{len} entries for {n} vertices (need none or one per vertex)"),
    };
    for (field, len) in [("normals", mesh.normals.len()), ("uvs", mesh.uvs.len()), ("colors", mesh.colors.len())] {
        if len != 0 && len != n {
            return Err(unmatched(field, len));
        }
    }
    if let Some((t, tri)) = mesh.triangles.iter().enumerate().find(|(_, tri)| tri.iter().any(|&i| i as usize >= n)) {
        return Err(ExportError::Unrepresentable {
            field: format!("triangles[{t}]"),
            message: format!("{tri:?} refers past the {n} vertices"),
        });
    }
    check_vectors(&mesh.positions, precision, format, "positions")?;
    if precision == Precision::Single {
        check_single_precision_triangles(mesh, format)?;
    }
    check_vectors(&mesh.normals, precision, format, "normals")?;
    check_vectors(&mesh.uvs, precision, format, "uvs")?;
    for (i, c) in mesh.colors.iter().enumerate() {
        for (k, &x) in c.iter().enumerate() {
            check_value(x as f64, Precision::Single, format, || format!("colors[{i}][{k}]"))?;
        }
    }
    Ok(())
}

/// `name` with control characters (line breaks) replaced, for formats that put a name on a
/// line of its own.
pub fn one_line(name: &str) -> String {
    name.replace(|c: char| c.is_control(), "_")
}

/// The mesh as a format of 32-bit floats (STL, glTF) stores it: a triangle two of whose
/// corners are one point in f32 has no area in the file (the pinch of a horn torus, whose
/// tube meets itself at the centre; a cone's apex), so it is dropped and the rest written.
/// Borrowed when no triangle is dropped; refused (with the first such triangle named)
/// when every triangle would be, the mesh being too fine or too small for its distance
/// from the origin. Triangles referring past the vertices are left for [`check_mesh`].
pub fn single_precision_triangles<'m>(
    mesh: &'m crate::TriangleMesh,
    format: &str,
) -> Result<std::borrow::Cow<'m, crate::TriangleMesh>, ExportError> {
    let n = mesh.positions.len();
    let single = |i: u32| mesh.positions[i as usize].map(|x| x as f32);
    let collapsed = |tri: &[u32; 3]| {
        tri.iter().all(|&i| (i as usize) < n)
            && (0..3).any(|k| tri[k] != tri[(k + 1) % 3] && single(tri[k]) == single(tri[(k + 1) % 3]))
    };
    if !mesh.triangles.iter().any(collapsed) {
        return Ok(std::borrow::Cow::Borrowed(mesh));
    }
    let kept: Vec<[u32; 3]> = mesh.triangles.iter().filter(|t| !collapsed(t)).copied().collect();
    if kept.is_empty() {
        check_single_precision_triangles(mesh, format)?;
    }
    Ok(std::borrow::Cow::Owned(crate::TriangleMesh { triangles: kept, ..mesh.clone() }))
}

/// Refuses a triangle two of whose corners are one point in 32-bit floats (a mesh too fine
/// for its distance from the origin, or too small): it would be degenerate in the file.
fn check_single_precision_triangles(mesh: &crate::TriangleMesh, format: &str) -> Result<(), ExportError> {
    let single = |i: u32| mesh.positions[i as usize].map(|x| x as f32);
    for (t, tri) in mesh.triangles.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (tri[k], tri[(k + 1) % 3]);
            if a != b && single(a) == single(b) {
                return Err(ExportError::Unrepresentable {
                    field: format!("triangles[{t}]"),
                    message: format!(
                        "vertices {a} and {b} are the same point {:?} in the 32-bit floats that {format} stores \
                         (the mesh is too fine or too small for its distance from the origin)",
                        single(a)
                    ),
                });
            }
        }
    }
    Ok(())
}
