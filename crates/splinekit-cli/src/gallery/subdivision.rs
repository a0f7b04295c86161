//! Gallery figures of subdivision surfaces: Catmull–Clark and Doo–Sabin on the cube, each
//! shaded after four steps inside its control cage.

use anyhow::{Result, anyhow};
use splinekit_mesh::export::{GltfGeometry, GltfScene};
use splinekit_mesh::subdivision_surface::{SurfaceScheme, read_obj_polygons};
use splinekit_render::{Camera, Image, LineItem, MeshItem, PointItem, RenderScene, Renderer};

/// A rendered figure: file stem, caption, picture, glb bytes, the picture's camera.
pub type Figure = (String, String, Image, Vec<u8>, Camera);

/// One figure per scheme.
pub fn figures(renderer: &Renderer) -> Result<Vec<Figure>> {
    let cage = read_obj_polygons(include_str!("../../../../examples/meshes/cube.obj"))
        .map_err(|e| anyhow!("cube.obj: {e}"))?;
    let mut out = Vec::new();
    for (scheme, stem, caption, color) in [
        (
            SurfaceScheme::CatmullClark,
            "catmull_clark_cube",
            "Catmull–Clark subdivision of a cube, four steps, inside its control cage (examples/meshes/cube.obj).",
            [0.2, 0.55, 0.8, 1.0],
        ),
        (
            SurfaceScheme::DooSabin,
            "doo_sabin_cube",
            "Doo–Sabin subdivision of the same cube, four steps: the biquadratic counterpart.",
            [0.85, 0.45, 0.2, 1.0],
        ),
    ] {
        let mesh = cage.subdivide(scheme, 4)?.triangulate();
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
            scene.lines.push(LineItem { points: pts, closed: true, color: [0.3, 0.3, 0.3, 1.0], width: 1.5 });
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
