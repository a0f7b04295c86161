//! The rendered scenes of the gallery: `examples/scenes/*.json`, embedded.

/// (file stem, scene JSON, caption).
pub const SCENES: &[(&str, &str, &str)] = &[
    (
        "bspline_polygon",
        include_str!("../../../../examples/scenes/bspline_polygon.json"),
        "A cubic B-spline from control points, with its control polygon.",
    ),
    (
        "rose_and_blending_copy",
        include_str!("../../../../examples/scenes/rose_and_blending_copy.json"),
        "The 3-D rose model curve (cyan) and its blending-spline copy (24 cubic Bézier locals, ERBS; shifted by moving every local frame).",
    ),
    (
        "heart_local_curves",
        include_str!("../../../../examples/scenes/heart_local_curves.json"),
        "The heart as a blending spline of 10 quadratic Bézier local curves (each in its own colour, with its interpolation point).",
    ),
    (
        "heart_transformed",
        include_str!("../../../../examples/scenes/heart_transformed.json"),
        "The heart blending spline after translating and rotating local curves (pink), against the model (cyan) — the seed's figure 6.",
    ),
    (
        "beating_heart",
        include_str!("../../../../examples/scenes/beating_heart.json"),
        "The beating heart: locals 1–4 and 6–9 move along x, 0 and 5 along y, 1, 2, 8, 9 also swing (ERBS, sub-curve locals).",
    ),
    (
        "plane_before",
        include_str!("../../../../examples/scenes/plane_before.json"),
        "Blending-spline plane, 5×5 bicubic Bézier local patches (ERBS), before transforming.",
    ),
    (
        "plane_after",
        include_str!("../../../../examples/scenes/plane_after.json"),
        "The plane after translating, rotating and scaling four local patches.",
    ),
    (
        "plane_animated",
        include_str!("../../../../examples/scenes/plane_animated.json"),
        "The plane's patches animated (oscillate, swing, pulse).",
    ),
    (
        "cylinder_before",
        include_str!("../../../../examples/scenes/cylinder_before.json"),
        "Blending-spline cylinder (closed in u), 8×4 bicubic local patches, before transforming.",
    ),
    (
        "cylinder_after",
        include_str!("../../../../examples/scenes/cylinder_after.json"),
        "The cylinder after moving a ring of patches outwards and turning one.",
    ),
    (
        "cylinder_animated",
        include_str!("../../../../examples/scenes/cylinder_animated.json"),
        "The cylinder breathing: a ring of patches oscillating with phases around the ring.",
    ),
    (
        "torus_before",
        include_str!("../../../../examples/scenes/torus_before.json"),
        "Blending-spline torus (closed in u and v), 8×6 bicubic local patches, before transforming.",
    ),
    (
        "torus_after",
        include_str!("../../../../examples/scenes/torus_after.json"),
        "The torus after moving, turning and scaling local patches.",
    ),
    (
        "torus_animated",
        include_str!("../../../../examples/scenes/torus_animated.json"),
        "The torus animated: a wave of patches around the outer equator, one patch spinning.",
    ),
    (
        "blending_torus_local_patches",
        include_str!("../../../../examples/scenes/blending_torus_local_patches.json"),
        "The local patches of a 6×4 blending-spline torus over their supports (one lifted), each in its own colour.",
    ),
    (
        "bezier_surface",
        include_str!("../../../../examples/scenes/bezier_surface.json"),
        "A bicubic Bézier surface with its control net.",
    ),
    (
        "nurbs_torus",
        include_str!("../../../../examples/scenes/nurbs_torus.json"),
        "The exact NURBS torus (biquadratic, 9×9 control points with weights) and its control net.",
    ),
    (
        "trimmed_surface",
        include_str!("../../../../examples/scenes/trimmed_surface.json"),
        "The Bézier surface trimmed by a closed Catmull–Rom outer loop and a NURBS circle hole, meshed by constrained Delaunay triangulation in the parameter plane.",
    ),
    (
        "surface_of_revolution",
        include_str!("../../../../examples/scenes/surface_of_revolution.json"),
        "A surface of revolution of a cubic Bézier profile, with parameter lines.",
    ),
    (
        "sweep_trefoil",
        include_str!("../../../../examples/scenes/sweep_trefoil.json"),
        "A circle swept along the trefoil knot with a rotation-minimising frame.",
    ),
    (
        "coons_patch",
        include_str!("../../../../examples/scenes/coons_patch.json"),
        "A bicubically blended Coons patch spanned by four Bézier boundary curves.",
    ),
    (
        "torus_gaussian_curvature",
        include_str!("../../../../examples/scenes/torus_gaussian_curvature.json"),
        "The torus coloured by Gaussian curvature (red positive, blue negative).",
    ),
    (
        "bezier_triangle_net",
        include_str!("../../../../examples/scenes/bezier_triangle_net.json"),
        "A cubic Bézier triangle with its triangular control net (lines of constant i, j and k); STEP writes it exactly as its degenerate bicubic patch.",
    ),
    (
        "gerbs_triangle_locals",
        include_str!("../../../../examples/scenes/gerbs_triangle_locals.json"),
        "A GERBS triangle: three quadratic Hermite locals of a triangle on a sphere (outlines, each in its colour with its corner), blended by rational ERBS weights; local v is moved up.",
    ),
    (
        "blending_sphere_moved",
        include_str!("../../../../examples/scenes/blending_sphere_moved.json"),
        "A blending surface over the icosphere (42 vertex locals in conformal charts, radial ERBS weights, smooth across every edge); one local moved out and scaled changes only its star.",
    ),
    (
        "blending_sphere_animated",
        include_str!("../../../../examples/scenes/blending_sphere_animated.json"),
        "The blending surface over the icosphere with three locals animated (oscillate, pulse).",
    ),
    ("klein_bottle", include_str!("../../../../examples/scenes/klein_bottle.json"), "The Klein bottle model surface."),
    ("seashell", include_str!("../../../../examples/scenes/seashell.json"), "The seashell model surface."),
    ("apple", include_str!("../../../../examples/scenes/apple.json"), "The apple model surface."),
    ("mobius", include_str!("../../../../examples/scenes/mobius.json"), "The Möbius strip model surface."),
    (
        "subdivision_surfaces",
        include_str!("../../../../examples/scenes/subdivision_surfaces.json"),
        "Two subdivision_surface documents inside their cages: the Catmull–Clark limit of the cube with its top ring infinitely sharp and one bottom edge of sharpness 2.5, and Loop's limit of the cube split into triangle fans, meshed on the exact limit.",
    ),
];
