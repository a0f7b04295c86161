//! Reading a cage from OBJ text: `v x y z` vertices, `f i j k …` polygon faces (1-based or
//! negative indices, `v/vt/vn` corners) and OpenSubdiv's crease tags `t crease 2/1 A B S`
//! (0-based vertex indices A, B; sharpness S). Other lines are ignored. Errors name the line.

use super::cage::Crease;

/// The vertices, faces and creases of an OBJ text.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ObjCage {
    /// `v` lines.
    pub vertices: Vec<[f64; 3]>,
    /// `f` lines, 0-based.
    pub faces: Vec<Vec<u32>>,
    /// `t crease` tags.
    pub creases: Vec<Crease>,
}

/// Reads the cage of an OBJ text.
pub fn read_obj_cage(text: &str) -> Result<ObjCage, String> {
    let mut m = ObjCage::default();
    for (k, line) in text.lines().enumerate() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => {
                let v: Result<Vec<f64>, _> = words.take(3).map(str::parse).collect();
                let v = v.map_err(|e| format!("line {}: {e}", k + 1))?;
                if v.len() != 3 {
                    return Err(format!("line {}: a vertex needs 3 coordinates", k + 1));
                }
                m.vertices.push([v[0], v[1], v[2]]);
            }
            Some("f") => {
                let n = m.vertices.len() as i64;
                let face: Result<Vec<u32>, String> = words
                    .map(|c| {
                        let i: i64 =
                            c.split('/').next().unwrap_or("").parse().map_err(|e| format!("line {}: {e}", k + 1))?;
                        let idx = if i < 0 { n + i } else { i - 1 };
                        if idx < 0 || idx >= n {
                            return Err(format!("line {}: vertex {i} does not exist (there are {n})", k + 1));
                        }
                        Ok(idx as u32)
                    })
                    .collect();
                m.faces.push(face?);
            }
            Some("t") if words.clone().next() == Some("crease") => {
                let w: Vec<&str> = words.skip(1).collect();
                let bad =
                    || format!("line {}: a crease tag is `t crease 2/1 A B SHARPNESS`, got '{}'", k + 1, line.trim());
                if w.len() != 4 || w[0] != "2/1" {
                    return Err(bad());
                }
                let a: u32 = w[1].parse().map_err(|_| bad())?;
                let b: u32 = w[2].parse().map_err(|_| bad())?;
                let sharpness: f64 = w[3].parse().map_err(|_| bad())?;
                m.creases.push(Crease { a, b, sharpness });
            }
            _ => {}
        }
    }
    Ok(m)
}
