//! The file formats splinekit writes, named by their extensions, and what each kind of
//! object can be written as: the one list the command line (`tessellate`,
//! `subdivide-surface`, `convert`, `render`, `animate`), Python's `save`/`Mesh.save`/
//! `write_step` and the studio's export read, so a format is added in one place and every
//! refusal names the same extensions.

use std::path::Path;

/// A file format, known by its extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Format {
    /// Wavefront OBJ (`.obj`): triangles, polygons and `l` polylines, one group an object.
    Obj,
    /// Binary STL (`.stl`): triangles only, 32-bit floats.
    Stl,
    /// ASCII STL (`.stla`): triangles only.
    StlAscii,
    /// ASCII PLY (`.ply`): one mesh of vertices, triangles and edges.
    Ply,
    /// glTF 2.0 as JSON with embedded buffers (`.gltf`).
    Gltf,
    /// Binary glTF (`.glb`).
    Glb,
    /// An SVG drawing (`.svg`) of a curve's polyline.
    Svg,
    /// STEP AP214 (`.step`, `.stp`): exact geometry.
    Step,
    /// A PNG picture (`.png`).
    Png,
    /// An animated GIF (`.gif`).
    Gif,
    /// A shape or scene document (`.json`).
    Json,
}

impl Format {
    /// Every format, in the order messages list them.
    pub const ALL: [Format; 11] = [
        Format::Obj,
        Format::Stl,
        Format::StlAscii,
        Format::Ply,
        Format::Gltf,
        Format::Glb,
        Format::Svg,
        Format::Step,
        Format::Png,
        Format::Gif,
        Format::Json,
    ];

    /// The formats of triangle meshes (surfaces, scenes, meshes).
    pub const MESHES: &'static [Format] =
        &[Format::Obj, Format::Stl, Format::StlAscii, Format::Ply, Format::Gltf, Format::Glb];

    /// The formats of polylines (curves tessellated).
    pub const POLYLINES: &'static [Format] = &[Format::Obj, Format::Gltf, Format::Glb];

    /// The extension (lower case, without the dot).
    pub fn extension(self) -> &'static str {
        match self {
            Format::Obj => "obj",
            Format::Stl => "stl",
            Format::StlAscii => "stla",
            Format::Ply => "ply",
            Format::Gltf => "gltf",
            Format::Glb => "glb",
            Format::Svg => "svg",
            Format::Step => "step",
            Format::Png => "png",
            Format::Gif => "gif",
            Format::Json => "json",
        }
    }

    /// The format an extension names (any case, without the dot; `stp` is STEP).
    pub fn from_extension(ext: &str) -> Option<Format> {
        let ext = ext.to_ascii_lowercase();
        if ext == "stp" {
            return Some(Format::Step);
        }
        Format::ALL.into_iter().find(|f| f.extension() == ext)
    }

    /// The format of a path by its extension.
    pub fn of_path(path: &Path) -> Option<Format> {
        path.extension().and_then(|e| e.to_str()).and_then(Format::from_extension)
    }

    /// The format of an output named on the command line: what follows its last dot (so
    /// `.obj` alone is an OBJ file, as the commands have always read it); `None` without a
    /// dot.
    pub fn of_name(name: &str) -> Option<Format> {
        name.rsplit_once('.').and_then(|(_, ext)| Format::from_extension(ext))
    }

    /// The format of a mesh output named on the command line (`tessellate -o`,
    /// `subdivide-surface -o`): what follows its last dot, or the whole name where it has
    /// none (a file named `obj` is an OBJ file), as those commands have always read it.
    pub fn of_output(name: &str) -> Option<Format> {
        name.rsplit('.').next().and_then(Format::from_extension)
    }

    /// Whether the format holds triangle meshes.
    pub fn holds_triangles(self) -> bool {
        Format::MESHES.contains(&self)
    }

    /// Whether the format holds polylines (curves) beside its triangles: OBJ (`l`), PLY
    /// (edges) and glTF (line strips); STL holds triangles only.
    pub fn holds_lines(self) -> bool {
        matches!(self, Format::Obj | Format::Ply | Format::Gltf | Format::Glb)
    }

    /// Whether the format is glTF (`.gltf` or `.glb`).
    pub fn is_gltf(self) -> bool {
        matches!(self, Format::Gltf | Format::Glb)
    }
}

impl std::fmt::Display for Format {
    /// `.ext`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, ".{}", self.extension())
    }
}

/// Formats for a message: `.a, .b or .c`.
pub fn phrase(formats: &[Format]) -> String {
    let dotted: Vec<String> = formats.iter().map(Format::to_string).collect();
    match dotted.split_last() {
        Some((last, [])) => last.clone(),
        Some((last, rest)) => format!("{} or {last}", rest.join(", ")),
        None => String::new(),
    }
}

/// What is written to a mesh or drawing file, and so which formats it takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Subject {
    /// A curve: a polyline, or a drawing of it.
    Curve,
    /// A surface: a triangle mesh.
    Surface,
    /// A scene: every visible object in one file (OBJ a group each, STL and PLY one mesh).
    Scene,
    /// A mesh already made (Python's `Mesh`).
    Mesh,
    /// A subdivision cage refined (`subdivide-surface`): its polygons or limit mesh, or its
    /// limit surface as STEP patches.
    SubdivisionCage,
}

impl Subject {
    /// The formats it is written as by tessellation (`tessellate`, `subdivide-surface`,
    /// Python's `save`, the studio's export).
    pub fn formats(self) -> &'static [Format] {
        match self {
            Subject::Curve => &[Format::Svg, Format::Obj, Format::Gltf, Format::Glb],
            Subject::Surface | Subject::Scene | Subject::Mesh => Format::MESHES,
            Subject::SubdivisionCage => {
                &[Format::Obj, Format::Stl, Format::StlAscii, Format::Ply, Format::Gltf, Format::Glb, Format::Step]
            }
        }
    }

    /// The plural noun of messages (`curves`).
    pub fn noun(self) -> &'static str {
        match self {
            Subject::Curve => "curves",
            Subject::Surface => "surfaces",
            Subject::Scene => "scenes",
            Subject::Mesh => "meshes",
            Subject::SubdivisionCage => "subdivision surfaces",
        }
    }

    /// `format` when it is one of [`Self::formats`], else the refusal
    /// (`curves are written as .svg, .obj, .gltf or .glb, not 'x.stl'`, `shown` naming the
    /// file).
    pub fn check(self, format: Option<Format>, shown: &str) -> Result<Format, String> {
        format.filter(|f| self.formats().contains(f)).ok_or_else(|| self.refusal(shown))
    }

    /// The refusal of a file `shown` that is none of [`Self::formats`].
    pub fn refusal(self, shown: &str) -> String {
        format!("{} are written as {}, not '{shown}'", self.noun(), phrase(self.formats()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn extensions_round_trip_and_name_their_formats() {
        for f in Format::ALL {
            assert_eq!(Format::from_extension(f.extension()), Some(f));
            assert_eq!(Format::from_extension(&f.extension().to_ascii_uppercase()), Some(f));
        }
        assert_eq!(Format::from_extension("stp"), Some(Format::Step));
        assert_eq!(Format::from_extension("xyz"), None);
        assert_eq!(Format::of_path(Path::new("a/b.STLA")), Some(Format::StlAscii));
        assert_eq!(Format::of_path(Path::new("a/b")), None);
        assert_eq!(Format::of_name(".obj"), Some(Format::Obj));
        assert_eq!(Format::of_name("obj"), None);
        assert_eq!(Format::of_name("a.b/c.STP"), Some(Format::Step));
        assert_eq!(Format::of_output("obj"), Some(Format::Obj));
        assert_eq!(Format::of_output("a/b.ply"), Some(Format::Ply));
        assert_eq!(Format::of_output("a.b/obj"), None);
        assert_eq!(phrase(&[Format::Obj]), ".obj");
        assert_eq!(phrase(&[Format::Obj, Format::Ply]), ".obj or .ply");
        assert_eq!(
            Subject::Curve.check(Some(Format::Stl), "x.stl").unwrap_err(),
            "curves are written as .svg, .obj, .gltf or .glb, not 'x.stl'"
        );
        assert_eq!(Subject::Surface.check(Some(Format::StlAscii), "x.stla"), Ok(Format::StlAscii));
        assert_eq!(
            Subject::Scene.refusal("x.svg"),
            "scenes are written as .obj, .stl, .stla, .ply, .gltf or .glb, not 'x.svg'"
        );
        assert!(Subject::SubdivisionCage.formats().contains(&Format::StlAscii));
    }
}
