//! Gallery figures of subdivision surfaces, each shaded inside its control cage:
//! Catmull–Clark and Doo–Sabin on the cube (four steps), the creased cube's Catmull–Clark
//! limit surface (four steps moved onto the limit, with limit normals), and Loop on the
//! fan-triangulated cube.

use anyhow::{Result, anyhow};
use splinekit::Point;
use splinekit::subdivision::surface::{Cage, Scheme, SubdivisionSurface};
use splinekit_mesh::TriangleMesh;
use splinekit_mesh::export::{GltfGeometry, GltfScene};
use splinekit_mesh::subdivision_surface::{PolygonMesh, SurfaceScheme, read_obj_polygons};
use splinekit_render::{Camera, Image, LineItem, MeshItem, PointItem, RenderScene, Renderer};

use crate::commands::subdivide_surface::read_obj_creases;
use splinekit_mesh::limit_mesh::limit_mesh;

/// A rendered figure: file stem, caption, picture, glb bytes, the picture's camera.
pub type Figure = (String, String, Image, Vec<u8>, Camera);

/// The limit mesh (positions and normals on the limit surface, split along sharp
/// creases) after `steps` steps.
fn limit_triangles(cage: &PolygonMesh, creases_from: &str, scheme: Scheme, steps: usize) -> Result<TriangleMesh> {
    let c = Cage::new(cage.vertices.iter().map(|p| Point::<3>::new(p[0], p[1], p[2])).collect(), &cage.faces)
        .with_creases(read_obj_creases(creases_from).map_err(|e| anyhow!("{e}"))?);
    let s = SubdivisionSurface::new(c, scheme, true)?.subdivide(steps)?;
    Ok(limit_mesh(&s)?.triangles())
}

/// One figure per scheme.
pub fn figures(renderer: &Renderer) -> Result<Vec<Figure>> {
    let cube_text = include_str!("../../../../examples/meshes/cube.obj");
    let creased_text = include_str!("../../../../examples/meshes/creased_cube.obj");
    let cage = read_obj_polygons(cube_text).map_err(|e| anyhow!("cube.obj: {e}"))?;
    let creased = read_obj_polygons(creased_text).map_err(|e| anyhow!("creased_cube.obj: {e}"))?;
    let mut out = Vec::new();
    let entries = [
        (
            cage.subdivide(SurfaceScheme::CatmullClark, 4)?.triangulate(),
            &cage,
            "catmull_clark_cube",
            "Catmull–Clark subdivision of a cube, four steps, inside its control cage (examples/meshes/cube.obj).",
            [0.2, 0.55, 0.8, 1.0],
        ),
        (
            cage.subdivide(SurfaceScheme::DooSabin, 4)?.triangulate(),
            &cage,
            "doo_sabin_cube",
            "Doo–Sabin subdivision of the same cube, four steps: the biquadratic counterpart.",
            [0.85, 0.45, 0.2, 1.0],
        ),
        (
            limit_triangles(&creased, creased_text, Scheme::CatmullClark, 4)?,
            &creased,
            "creased_cube_limit",
            "The Catmull–Clark limit surface of a creased cube (examples/meshes/creased_cube.obj): the top ring \
             infinitely sharp, one bottom edge of sharpness 2.5; four steps moved onto the limit with limit normals.",
            [0.3, 0.7, 0.45, 1.0],
        ),
        (
            limit_triangles(&cage, "", Scheme::Loop, 4)?,
            &cage,
            "loop_cube_limit",
            "Loop subdivision of the cube split into triangle fans: the limit surface after four steps, \
             beside the quad cage.",
            [0.75, 0.35, 0.6, 1.0],
        ),
    ];
    for (mesh, cage, stem, caption, color) in entries {
        let f = |v: &[[f64; 3]]| v.iter().map(|p| p.map(|x| x as f32)).collect::<Vec<_>>();
        let mut scene = RenderScene {
            meshes: vec![MeshItem {
                positions: f(&mesh.positions),
                normals: f(&mesh.normals),
                color,
                triangles: mesh.triangles.clone(),
                ..Default::default()
            }],
            ..Default::default()
        };
        for face in &cage.faces {
            let pts = face.iter().map(|&i| cage.vertices[i as usize].map(|x| x as f32)).collect();
            scene.lines.push(LineItem {
                points: pts,
                closed: true,
                color: [0.3, 0.3, 0.3, 1.0],
                width: 1.5,
                colors: Vec::new(),
            });
        }
        for v in &cage.vertices {
            scene.points.push(PointItem { position: v.map(|x| x as f32), color: [0.1, 0.1, 0.1, 1.0], size: 8.0 });
        }
        let bounds = scene.bounds().expect("a cube has bounds");
        let camera = Camera::fit(bounds, 0.7, 0.45, 4.0 / 3.0);
        scene.camera = Some(camera);
        let img = renderer.render(&scene, 640, 480)?;
        let glb = GltfScene::single(stem, GltfGeometry::Mesh(mesh), color).to_glb()?;
        out.push((stem.to_string(), caption.to_string(), img, glb, camera));
    }
    Ok(out)
}
