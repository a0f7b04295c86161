//! Reading inputs: shape documents, point lists (CSV or JSON) and number lists.

use anyhow::{Context, Result, anyhow, bail};
use serde_json::Value;
use splinekit_scene::ShapeDocument;

/// Reads a file, or standard input for `-`, refusing text too large to parse within the
/// budget before reading it (standard input: as soon as it grows past that size).
pub fn read_text(path: &str, what: &str) -> Result<String> {
    use std::io::Read;
    let limit = crate::budget::max_input_bytes() as u64;
    let mut text = String::new();
    if path == "-" {
        let read = std::io::stdin()
            .take(limit + 1)
            .read_to_string(&mut text)
            .with_context(|| format!("{what}: cannot read standard input"))?;
        if read as u64 > limit {
            return Err(crate::budget::input_too_large(what));
        }
    } else {
        let mut file = std::fs::File::open(path).map_err(|e| anyhow!("{what}: cannot read '{path}': {e}"))?;
        if let Ok(meta) = file.metadata()
            && meta.is_file()
        {
            crate::budget::check_input(what, meta.len() as f64)?;
        }
        let read = (&mut file)
            .take(limit + 1)
            .read_to_string(&mut text)
            .map_err(|e| anyhow!("{what}: cannot read '{path}': {e}"))?;
        if read as u64 > limit {
            return Err(crate::budget::input_too_large(what));
        }
    }
    Ok(text)
}

/// The folder that paths inside the document at `path` are relative to: the file's own
/// folder, or the current folder for standard input.
pub fn document_folder(path: &str) -> std::path::PathBuf {
    match std::path::Path::new(path).parent() {
        Some(p) if path != "-" && !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => std::path::PathBuf::from("."),
    }
}

/// Reads and parses a shape or scene document (`what` names the input in errors), reading
/// the cage files of subdivision surfaces relative to its folder; a STEP file (by its
/// extension, `.step` or `.stp`) is read as the documents of its objects
/// ([`read_step_document`]).
pub fn read_document(path: &str, what: &str) -> Result<splinekit_scene::SceneOrShape> {
    if is_step(path) {
        return read_step_document(path, what);
    }
    let text = read_text(path, what)?;
    Ok(splinekit_scene::SceneOrShape::from_json_in(&text, &document_folder(path))?)
}

/// Whether the path names a STEP file (`.step`, `.stp`, any case).
pub fn is_step(path: &str) -> bool {
    let lower = path.to_ascii_lowercase();
    lower.ends_with(".step") || lower.ends_with(".stp")
}

/// A STEP file's objects as documents: its one object as a shape, several as a scene of
/// them (solids and shells as `brep` documents; see `splinekit_step::documents`). What it
/// does not convert is listed on standard error, one warning a kind, as `convert` does.
pub fn read_step_document(path: &str, what: &str) -> Result<splinekit_scene::SceneOrShape> {
    let file = if path == "-" {
        splinekit_step::part21::StepFile::from_reader(std::io::stdin().lock())
    } else {
        splinekit_step::part21::StepFile::open(std::path::Path::new(path))
    }
    .map_err(|e| anyhow!("{what}: {e}"))?;
    let imported = splinekit_step::documents::import_items(&file).map_err(|e| anyhow!("{what}: {e}"))?;
    for (name, count) in &imported.not_understood {
        eprintln!("warning: {count} × {name} not converted (no splinekit equivalent yet)");
    }
    if imported.items.is_empty() {
        bail!("{what}: the file holds no curve or surface that splinekit reads");
    }
    // The same document `convert` writes: parts placed by the product structure.
    splinekit_scene::SceneOrShape::from_value(imported.to_value()).map_err(|e| anyhow!("{what}: {e}"))
}

/// Reads and parses a shape document; a scene is refused with its object count, for the
/// commands that compare or combine shapes (`intersect`), where "each object" has no one
/// meaning. The commands that answer for one shape take scenes through [`read_shapes`].
pub fn read_shape(path: &str) -> Result<ShapeDocument> {
    match read_document(path, "SHAPE")? {
        splinekit_scene::SceneOrShape::Shape(doc) => Ok(doc),
        splinekit_scene::SceneOrShape::Scene(scene) => bail!(
            "SHAPE: a scene of {} objects, but this command takes one shape (pick one of its \"objects\")",
            scene.objects.len()
        ),
    }
}

/// What a command that answers for one shape reads: a shape document, or a scene (what
/// `splinekit offset` prints for an offset of several pieces) whose objects it answers for
/// one by one.
pub enum Shapes {
    /// One shape document.
    One(ShapeDocument),
    /// A scene: its objects' shapes in order, and its JSON as written (for the commands
    /// that write a scene back, keeping the camera, lights and styles).
    Scene(Vec<ShapeDocument>, Value),
}

/// Reads and parses a shape document or a scene.
pub fn read_shapes(path: &str) -> Result<Shapes> {
    let text = read_text(path, "SHAPE")?;
    match splinekit_scene::SceneOrShape::from_json_in(&text, &document_folder(path))? {
        splinekit_scene::SceneOrShape::Shape(doc) => Ok(Shapes::One(doc)),
        splinekit_scene::SceneOrShape::Scene(scene) => {
            let value: Value = serde_json::from_str(&text).context("SHAPE: invalid JSON")?;
            Ok(Shapes::Scene(scene.objects.into_iter().map(|o| o.shape).collect(), value))
        }
    }
}

impl Shapes {
    /// The answer for one shape, or `{"objects": [ANSWER, …]}` for a scene, each ANSWER
    /// what the object alone gives. Every object is answered before anything is returned,
    /// and an error names the object (`objects[2].shape: …`).
    pub fn answer_each(self, mut answer: impl FnMut(ShapeDocument) -> Result<Value>) -> Result<Value> {
        match self {
            Shapes::One(doc) => answer(doc),
            Shapes::Scene(docs, _) => {
                let answers = docs
                    .into_iter()
                    .enumerate()
                    .map(|(i, doc)| answer(doc).map_err(|e| anyhow!("objects[{i}].shape: {e}")))
                    .collect::<Result<Vec<_>>>()?;
                Ok(serde_json::json!({ "objects": answers }))
            }
        }
    }

    /// The shape that `make` gives for one shape, or for a scene the same scene (camera,
    /// lights, background, styles as written) with each object's shape replaced by what
    /// `make` gives for it. When `make` gives a scene (an offset of several pieces), its
    /// objects take the place of the one object, each with that object's style and points.
    /// An error names the object.
    pub fn map_each(self, mut make: impl FnMut(ShapeDocument) -> Result<Value>) -> Result<Value> {
        match self {
            Shapes::One(doc) => make(doc),
            Shapes::Scene(docs, mut scene) => {
                let written = scene.get_mut("objects").and_then(Value::as_array_mut).map(std::mem::take);
                let written = written.ok_or_else(|| anyhow!("SHAPE: the scene has no \"objects\" list"))?;
                let mut objects = Vec::with_capacity(written.len());
                for (i, (doc, mut object)) in docs.into_iter().zip(written).enumerate() {
                    let made = make(doc).map_err(|e| anyhow!("objects[{i}].shape: {e}"))?;
                    let pieces: Vec<Value> = if made.get("type").and_then(Value::as_str) == Some("scene") {
                        made["objects"].as_array().into_iter().flatten().map(|o| o["shape"].clone()).collect()
                    } else {
                        vec![made]
                    };
                    for piece in pieces {
                        object["shape"] = piece;
                        objects.push(object.clone());
                    }
                }
                scene["objects"] = Value::Array(objects);
                Ok(scene)
            }
        }
    }
}

/// Reads points: a JSON array of points (or `{"points": [...]}`), or CSV text with one
/// point per line (separated by commas, semicolons or white space; `#` starts a comment;
/// a first line with letters is taken as a header).
pub fn read_points(path: &str) -> Result<Vec<Vec<f64>>> {
    parse_points(&read_text(path, "POINTS")?)
}

/// Parses points given as text (see [`read_points`]).
pub fn parse_points(text: &str) -> Result<Vec<Vec<f64>>> {
    let trimmed = text.trim_start();
    let pts = if trimmed.starts_with('[') || trimmed.starts_with('{') {
        parse_json_points(trimmed)?
    } else {
        parse_csv_points(text)?
    };
    if pts.is_empty() {
        bail!("points: the input holds no points");
    }
    let d = pts[0].len();
    for (i, p) in pts.iter().enumerate() {
        if p.len() != d {
            bail!("points[{i}]: expected {d} coordinates like the first point, got {}", p.len());
        }
        if let Some((j, v)) = p.iter().enumerate().find(|(_, v)| !v.is_finite()) {
            bail!("points[{i}][{j}]: coordinate is not finite ({v})");
        }
        for (j, &v) in p.iter().enumerate() {
            splinekit_scene::points::check_magnitude(format_args!("points[{i}][{j}]"), v)?;
        }
    }
    Ok(pts)
}

fn parse_json_points(text: &str) -> Result<Vec<Vec<f64>>> {
    let v: Value = serde_json::from_str(text).map_err(|e| anyhow!("points: invalid JSON: {e}"))?;
    let arr = match &v {
        Value::Array(a) => a,
        Value::Object(m) => match m.get("points") {
            Some(Value::Array(a)) if m.len() == 1 => a,
            _ => bail!("points: expected an array of points or {{\"points\": [...]}}"),
        },
        _ => bail!("points: expected an array of points"),
    };
    arr.iter()
        .enumerate()
        .map(|(i, p)| {
            let Value::Array(coords) = p else { bail!("points[{i}]: expected an array of numbers") };
            coords
                .iter()
                .enumerate()
                .map(|(j, c)| c.as_f64().ok_or_else(|| anyhow!("points[{i}][{j}]: expected a number, got {c}")))
                .collect()
        })
        .collect()
}

fn parse_csv_points(text: &str) -> Result<Vec<Vec<f64>>> {
    let mut out = Vec::new();
    for (lineno, raw) in text.lines().enumerate() {
        let line = raw.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let fields: Vec<&str> =
            line.split(|c: char| c == ',' || c == ';' || c.is_whitespace()).filter(|s| !s.is_empty()).collect();
        if out.is_empty() && fields.iter().any(|f| f.chars().any(|c| c.is_alphabetic()) && f.parse::<f64>().is_err()) {
            // A header line.
            continue;
        }
        let p: Result<Vec<f64>> = fields
            .iter()
            .map(|f| f.parse::<f64>().map_err(|_| anyhow!("points: line {}: '{f}' is not a number", lineno + 1)))
            .collect();
        out.push(p?);
    }
    Ok(out)
}

/// Parses a comma-separated list of finite numbers for option `name`.
pub fn parse_numbers(name: &str, text: &str) -> Result<Vec<f64>> {
    let values: Result<Vec<f64>> = text
        .split(',')
        .map(|s| {
            let s = s.trim();
            let v: f64 = s.parse().map_err(|_| anyhow!("{name}: '{s}' is not a number"))?;
            if !v.is_finite() {
                bail!("{name}: {s} is not a finite number");
            }
            Ok(v)
        })
        .collect();
    let values = values?;
    if values.is_empty() {
        bail!("{name}: expected at least one number");
    }
    Ok(values)
}
