// splinekit-render: meshes (two-sided Blinn–Phong, two directional lights), lines of a
// screen width, and points as discs.

struct Globals {
    view_proj: mat4x4<f32>,
    eye: vec4<f32>,
    // width, height (pixels), depth bias for lines, unused
    viewport: vec4<f32>,
    // direction the light shines towards (xyz), intensity (w)
    light0: vec4<f32>,
    light1: vec4<f32>,
    // ambient (x)
    ambient: vec4<f32>,
};

@group(0) @binding(0) var<uniform> g: Globals;

struct MeshOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) color: vec4<f32>,
};

@vertex
fn vs_mesh(@location(0) p: vec3<f32>, @location(1) n: vec3<f32>, @location(2) c: vec4<f32>) -> MeshOut {
    var out: MeshOut;
    out.clip = g.view_proj * vec4<f32>(p, 1.0);
    out.world = p;
    out.normal = n;
    out.color = c;
    return out;
}

fn shade_light(n: vec3<f32>, v: vec3<f32>, light: vec4<f32>) -> vec2<f32> {
    let l = normalize(-light.xyz);
    let diffuse = max(dot(n, l), 0.0) * light.w;
    let h = normalize(l + v);
    let specular = pow(max(dot(n, h), 0.0), 48.0) * 0.3 * light.w;
    return vec2<f32>(diffuse, specular);
}

@fragment
fn fs_mesh(in: MeshOut) -> @location(0) vec4<f32> {
    var n = in.normal;
    if (dot(n, n) < 1e-8) {
        n = cross(dpdx(in.world), dpdy(in.world));
    }
    n = normalize(n);
    let v = normalize(g.eye.xyz - in.world);
    if (dot(n, v) < 0.0) {
        n = -n;
    }
    let a = shade_light(n, v, g.light0);
    let b = shade_light(n, v, g.light1);
    // A headlight keeps faces turned from both lights readable.
    let head = 0.25 * max(dot(n, v), 0.0);
    let rgb = in.color.rgb * (g.ambient.x + a.x + b.x + head) + vec3<f32>(a.y + b.y);
    return vec4<f32>(rgb, in.color.a);
}

struct FlatOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) color: vec4<f32>,
    @location(1) local: vec2<f32>,
    @location(2) size: f32,
};

@vertex
fn vs_line(@builtin(vertex_index) vi: u32, @location(0) a: vec3<f32>, @location(1) b: vec3<f32>,
           @location(2) color: vec4<f32>, @location(3) width: f32) -> FlatOut {
    let ca = g.view_proj * vec4<f32>(a, 1.0);
    let cb = g.view_proj * vec4<f32>(b, 1.0);
    let half_view = 0.5 * g.viewport.xy;
    let sa = ca.xy / ca.w * half_view;
    let sb = cb.xy / cb.w * half_view;
    var dir = sb - sa;
    if (length(dir) < 1e-6) {
        dir = vec2<f32>(1.0, 0.0);
    }
    dir = normalize(dir);
    let perp = vec2<f32>(-dir.y, dir.x);
    var ends = array<f32, 6>(0.0, 1.0, 1.0, 0.0, 1.0, 0.0);
    var sides = array<f32, 6>(-1.0, -1.0, 1.0, -1.0, 1.0, 1.0);
    let e = ends[vi];
    let s = sides[vi];
    var c = ca;
    if (e > 0.5) {
        c = cb;
    }
    let ext = (2.0 * e - 1.0) * dir * (0.5 * width) + s * perp * (0.5 * width);
    var out: FlatOut;
    out.clip = vec4<f32>(c.xy + ext / half_view * c.w, c.z - g.viewport.z * c.w, c.w);
    out.color = color;
    out.local = vec2<f32>(0.0, s);
    out.size = width;
    return out;
}

@fragment
fn fs_flat(in: FlatOut) -> @location(0) vec4<f32> {
    return in.color;
}

@vertex
fn vs_point(@builtin(vertex_index) vi: u32, @location(0) p: vec3<f32>, @location(1) size: f32,
            @location(2) color: vec4<f32>) -> FlatOut {
    var xs = array<f32, 6>(-1.0, 1.0, 1.0, -1.0, 1.0, -1.0);
    var ys = array<f32, 6>(-1.0, -1.0, 1.0, -1.0, 1.0, 1.0);
    let corner = vec2<f32>(xs[vi], ys[vi]);
    let c = g.view_proj * vec4<f32>(p, 1.0);
    var out: FlatOut;
    out.clip = vec4<f32>(c.xy + corner * (0.5 * size + 1.0) / (0.5 * g.viewport.xy) * c.w, c.z - 2.0 * g.viewport.z * c.w, c.w);
    out.color = color;
    out.local = corner * (0.5 * size + 1.0);
    out.size = size;
    return out;
}

@fragment
fn fs_point(in: FlatOut) -> @location(0) vec4<f32> {
    let r = length(in.local);
    let alpha = clamp(0.5 * in.size - r + 0.5, 0.0, 1.0);
    if (alpha <= 0.0) {
        discard;
    }
    return vec4<f32>(in.color.rgb, in.color.a * alpha);
}
