"""Feeds the splinekit binary random, often malformed shape documents and options.

Every run must end with exit status 0 and output, or exit status 2 with exactly one
line on standard error and nothing on standard output: never a panic, a hang or an
internal error (CONTRACT.md section 3). Standard library only.

Usage: python3 .ci/fuzz_cli.py BINARY [SEED] [CASES]
"""
import json, os, random, re, shutil, subprocess, sys, tempfile
B = sys.argv[1]
random.seed(int(sys.argv[2]) if len(sys.argv) > 2 else 1)
TMP = tempfile.mkdtemp()
SVG, OBJ, STL, GLB, PNG = (os.path.join(TMP, "fuzz." + e) for e in ("svg", "obj", "stl", "glb", "png"))
def registry():
    """The curve and surface types of the binary's registry, read from its message for an
    unknown type, so that a new kind is fuzzed without an edit here (its fields below, where
    this file knows them; otherwise its defaults, with the stray fields every kind gets)."""
    r = subprocess.run([B, "eval", "-", "--at", "0"], input='{"type": "?"}', capture_output=True, text=True, timeout=20)
    m = re.search(r"curves: ([^;]+); surfaces: ([^)]+)\)", r.stderr)
    if not m:
        sys.exit(f"fuzz: no list of types in the message for an unknown type: {r.stderr.strip()}")
    return [t.strip() for t in m.group(1).split(",")], [t.strip() for t in m.group(2).split(",")]
CURVES, SURFACES = registry()
def num():
    return random.choice([0, 1, -1, 0.5, 2, 3, 1e300, -1e300, 1e-300, 7, 100000, -0.0, 1e9, 0.25, 12, "x", None, [], True])
def pt(d):
    return [num() if random.random() < 0.15 else random.uniform(-3, 3) for _ in range(d)]
def pts(n, d):
    return [pt(d if random.random() > 0.05 else d + 1) for _ in range(n)]
def knots(n):
    k = sorted(random.uniform(0, 5) for _ in range(n))
    if random.random() < 0.3: k = [0]*4 + sorted(k[4:]) 
    if random.random() < 0.1: random.shuffle(k)
    return k
def animation(local):
    m = random.choice([{"oscillate": {"direction": pt(random.choice([2, 3])), "amplitude": num()}},
                       {"rotate": {"axis": pt(3), "speed": num(), "pivot": pt(3)}},
                       {"swing": {"axis": pt(random.choice([2, 3])), "amplitude": num(), "frequency": num()}},
                       {"pulse": {"amplitude": num()}}, {"spin": {}}, 3])
    return random.choice([[{"local": local, "motions": [m]}], [{"local": local}], {"0": m}])
def curve(depth=0):
    t = random.choice(CURVES) if depth < 2 else "line"
    d = random.choice([1,2,3,3,3,4,5])
    n = random.choice([0,1,2,3,4,5,8])
    p = random.choice([0,1,2,3,5,-1,100000])
    doc = {"type": t}
    if t in ("bezier","rational_bezier"): doc["control_points"] = pts(n, d)
    if t == "rational_bezier": doc["weights"] = [random.choice([1, 0.5, 0, -1, 2]) for _ in range(n + random.choice([0,0,1]))]
    if t in ("bspline","nurbs"):
        doc.update(degree=p, knots=knots(n + max(p,0) + 1 + random.choice([0,0,0,-1,1])) if p < 1000 else [0,1], control_points=pts(n, d))
        if random.random() < 0.3: doc["periodic"] = True
    if t == "nurbs": doc["weights"] = [random.choice([1, 0.5, 0, 2]) for _ in range(n)]
    if t in ("hermite",): doc.update(points=pts(n, d), tangents=pts(n + random.choice([0,0,1]), d))
    if t == "catmull_rom": doc.update(points=pts(n, d), alpha=random.choice([0, 0.5, 1, 2, -1]), closed=random.random() < 0.5)
    if t == "line": doc.update({"from": pt(d), "to": pt(d)})
    if t in ("circle","rose","helix"): doc["radius"] = num()
    if t == "rose": doc["n"] = num()
    if t == "logarithmic_spiral": doc.update({f: num() for f in ("a", "b", "turns") if random.random() < 0.6})
    if t == "chrysanthemum" and random.random() < 0.7: doc["scale"] = num()
    if t == "bfunction" or (t == "blend" and random.random() < 0.7):
        bt = random.choice(["linear", "polynomial", "beta", "trigonometric", "half_cosine", "rational", "erbs", "erbs", "nope"])
        bf = {"type": bt}
        if bt == "polynomial": bf["smoothness"] = random.choice([0, 1, 2, 5, 31, -1, "x"])
        if bt == "beta": bf.update(a=random.choice([0, 1, 3, 70]), b=random.choice([0, 2, 3]))
        if bt == "erbs":
            for key in ("alpha", "beta", "gamma", "lambda"):
                if random.random() < 0.4: bf[key] = num()
        doc["bfunction"] = bf
    if t == "blend": doc.update(first=curve(depth + 1), second=curve(depth + 1), overlap=num())
    if t == "blending_spline":
        doc.update(model=curve(depth + 1), local_curves=random.choice([0, 1, 2, 3, 10, 100001, -1]))
        if random.random() < 0.5: doc["local"] = random.choice([{"type": "bezier", "degree": random.choice([0, 1, 3, 21])}, {"type": "sub_curve"}, {"type": "arc"}])
        if random.random() < 0.5: doc["closed"] = random.random() < 0.5
        if random.random() < 0.5:
            tr = {"translate": pt(random.choice([2, 3])), "scale": num(), "rotate": {"axis": pt(3), "angle": num()}}
            doc["transforms"] = random.choice([[tr], {"0": tr}, {"x": tr}, {"7": tr}, 5])
        if random.random() < 0.3: doc["animation"] = animation(random.choice([0, 1, 9, [0, 1], -1]))
        if random.random() < 0.15:
            doc.pop("model", None); doc.pop("local", None)
            doc["knots"] = knots(random.choice([0, 2, 3, 4]))
            doc["local_curves"] = [curve(2) for _ in range(random.choice([0, 2, 3, 4]))]
        elif random.random() < 0.15:
            # Hermite data: a position and derivatives per knot, counts and shapes sometimes off.
            doc.pop("model", None); doc.pop("local", None); doc.pop("local_curves", None)
            n, order = random.choice([0, 2, 3, 4]), random.choice([1, 2, 3, 22])
            doc["knots"] = knots(n + random.choice([0, 0, 1]))
            doc["hermite"] = [pts(order + random.choice([0, 0, 0, 1]), d) for _ in range(n)]
    if t == "curve_on_surface":
        doc["curve"] = curve(2) if random.random() < 0.3 else {"type": "line", "from": pt(2), "to": pt(random.choice([2, 2, 3]))}
        doc["surface"] = surface(1) if depth < 1 and random.random() < 0.3 else {"type": random.choice(["torus", "plane", "sphere", "dini_surface"])}
    if random.random() < 0.05: doc["bogus"] = 1
    return doc
def surface(depth=0):
    t = random.choice(SURFACES)
    doc = {"type": t}
    d = random.choice([2,3,3,3])
    nu, nv = random.choice([0,1,2,3,4]), random.choice([1,2,3,4])
    if t in ("bezier_surface","bspline_surface","nurbs_surface"):
        doc["control_points"] = [pts(nv + (1 if random.random() < 0.05 else 0), d) for _ in range(nu)]
    if t in ("bspline_surface","nurbs_surface"):
        pu, pv = random.choice([0,1,2,3]), random.choice([0,1,2,3])
        doc.update(degree_u=pu, degree_v=pv, knots_u=knots(nu+pu+1), knots_v=knots(nv+pv+1))
        if random.random() < 0.2: doc["periodic_u"] = True
    if t == "nurbs_surface": doc["weights"] = [[random.choice([1, 2, 0]) for _ in range(nv)] for _ in range(nu)]
    if t in ("sphere","cylinder","cone"): doc["radius"] = num()
    if t == "torus": doc.update(major_radius=num(), minor_radius=num())
    # The catalogue's fields (a scale, semi-axes, radii).
    for f in {"asteroidal_sphere": "abc", "bohemian_dome": "abc", "dini_surface": "ab"}.get(t, ""):
        if random.random() < 0.5: doc[f] = num()
    if t in ("roman_surface",): doc["radius"] = num()
    if t == "inside_out_torus": doc.update(wheel_radius=num(), tube_radius_1=num(), tube_radius_2=num())
    if t in ("bent_horns","boy_surface","cross_cap","eight_surface","kuen_surface","sine_surface","slippers_surface","swallowtail","trianguloid_trefoil","whitney_umbrella") and random.random() < 0.7: doc["scale"] = num()
    if t in ("revolution","extrusion"): doc["curve"] = curve(1)
    if t == "extrusion": doc["direction"] = pt(random.choice([2,3]))
    if t == "revolution": doc["angle"] = num(); doc["axis"] = pt(3)
    if t == "ruled": doc.update(first=curve(1), second=curve(1))
    if t == "coons": doc.update(bottom=curve(2), top=curve(2), left=curve(2), right=curve(2))
    if t == "sweep": doc.update(profile=curve(1), path=curve(1))
    if t == "blending_spline_surface":
        doc.update(model=surface(1) if depth < 1 and random.random() < 0.3 else {"type": random.choice(["torus", "plane", "cylinder", "sphere", "enneper"])},
                   local_surfaces=random.choice([[4, 4], [2, 3], [0, 5], [3], [100000, 100000], [5, 1]]))
        if random.random() < 0.5: doc["local"] = random.choice([{"type": "bezier", "degree": random.choice([[3, 3], [0, 2], [13, 1], [2]])}, {"type": "sub_surface"}])
        if random.random() < 0.3: doc["closed_u"] = random.random() < 0.5
        if random.random() < 0.3: doc["transforms"] = random.choice([{"1,1": {"scale": num()}}, [[{}], [{"translate": pt(3)}]], {"a": {}}, 4])
        if random.random() < 0.3: doc["animation"] = animation(random.choice([[0, 1], [9, 0], 1]))
        if random.random() < 0.15:
            # Hermite data at knot pairs: rows of partials per pair, shapes sometimes off.
            doc.pop("model", None); doc.pop("local_surfaces", None); doc.pop("local", None)
            nu, nv, du, dv = random.choice([0, 2, 3]), random.choice([1, 2, 3]), random.choice([0, 1, 3, 13]), random.choice([1, 2])
            doc["knots_u"], doc["knots_v"] = knots(nu), knots(nv + random.choice([0, 0, 1]))
            doc["hermite"] = [[[pts(dv + 1, d) for _ in range(du + 1)] for _ in range(nv)] for _ in range(nu)]
    if t == "subdivision_surface":
        nvert = random.choice([0, 3, 4, 8])
        doc["vertices"] = pts(nvert, 3 if random.random() < 0.9 else 2)
        doc["faces"] = [[random.choice([0, 1, 2, 3, 7, -1]) for _ in range(random.choice([2, 3, 4, 5]))] for _ in range(random.choice([0, 1, 2, 6]))]
        if random.random() < 0.3: doc["scheme"] = random.choice(["catmull-clark", "loop", "bilinear", "doo-sabin"])
        if random.random() < 0.3: doc["creases"] = [{"edge": [random.choice([0, 1, 9]), random.choice([1, 2])], "sharpness": num()}]
        if random.random() < 0.2: doc["boundary"] = random.choice(["edge-only", "edge-and-corner", "none"])
        if random.random() < 0.2: doc["triangulate"] = True
        if random.random() < 0.1: doc["obj"] = random.choice(["missing.obj", "/dev/null", ""])
    if t == "sub_surface":
        doc["surface"] = surface(1) if depth < 1 and random.random() < 0.5 else {"type": random.choice(["torus", "plane", "sphere"])}
        doc["corners"] = random.choice([[pt(2) for _ in range(4)], [[0, 0], [1, 0], [1, 1], [0, 1]], [[0, 0], [1, 1], [1, 0], [0, 1]], [pt(2)], 5])
    if t == "bezier_triangle":
        doc["control_points"] = pts(random.choice([0, 1, 2, 3, 6, 10, 15]), d)
        if random.random() < 0.3: doc["weights"] = [random.choice([1, 0.5, 0, -1, 2]) for _ in range(random.choice([3, 6, 10]))]
        if random.random() < 0.2: doc["degree"] = random.choice([0, 1, 2, 3, 31, 10**12])
    if t == "sub_triangle":
        doc.update(surface=surface(1) if depth < 1 and random.random() < 0.3 else {"type": random.choice(["sphere", "torus", "plane"])},
                   corners=random.choice([[pt(2), pt(2), pt(2)], [[0, 0], [1, 0], [0, 1]], [[0, 0], [0, 0], [1, 1]], [pt(2)], 3]))
    if t == "gerbs_triangle":
        tri = {"type": "sub_triangle", "surface": {"type": "sphere"}, "corners": [[0.2, 0.1], [1, 0.2], [0.5, 0.9]]}
        if random.random() < 0.5: doc.update(model=random.choice([tri, surface(1) if depth < 1 else tri]), degree=random.choice([1, 3, 0, 31]))
        else: doc["locals"] = random.choice([[tri, tri, tri], [tri], [surface(1) if depth < 1 else tri] * 3])
        if random.random() < 0.3: doc["form"] = random.choice(["rational", "non_rational", "x"])
        if random.random() < 0.3: doc["bfunction"] = random.choice([{"type": "erbs"}, {"type": "beta", "a": 1, "b": 3}, {"type": "linear"}, {"type": "polynomial", "smoothness": 0}])
        if random.random() < 0.3: doc["transforms"] = random.choice([{"1": {"scale": num()}}, [{}, {"translate": pt(3)}], {"7": {}}])
        if random.random() < 0.3: doc["animation"] = animation(random.choice([0, 2, 9]))
    if t == "triangulation":
        n = random.choice([0, 2, 3, 5, 12])
        doc["points"] = pts(n, random.choice([2, 3, 3]))
        if random.random() < 0.4: doc["heights"] = [num() for _ in range(random.choice([n, n + 1]))]
        if random.random() < 0.3: doc["edges"] = [[random.choice([0, 1, 4, 99]), random.choice([0, 2, 3])]]
        if random.random() < 0.5: doc["interpolant"] = random.choice(["linear", "clough_tocher", "sibson"])
        if random.random() < 0.3: doc["normals"] = pts(random.choice([n, 1]), 3)
    if t == "blending_triangulation":
        doc["mesh"] = random.choice([
            {"type": "icosphere", "radius": num(), "subdivisions": random.choice([0, 1, 2, 40])},
            {"type": "torus", "segments": random.choice([[6, 4], [2, 9], [10**6, 10**6]])},
            {"type": "points", "vertices": pts(random.choice([0, 3, 6, 9]), 3)},
            {"type": "points", "vertices": pts(4, 3), "triangles": [[0, 1, 2], [random.choice([0, 2, 9]), 1, 3]], "normals": pts(random.choice([4, 2]), 3)},
            {"type": "cube"}])
        if random.random() < 0.3: doc["degree"] = random.choice([1, 2, 0, 3])
        if random.random() < 0.3: doc["transforms"] = random.choice([{"1": {"scale": num()}}, {"500": {}}, [{"translate": pt(3)}]])
        if random.random() < 0.3: doc["animation"] = animation(random.choice([0, 3, 999]))
    if t == "bicubic_hermite":
        dim = random.choice([2, 3, 3])
        corner = lambda: [[pt(dim), pt(dim)], [pt(dim), pt(dim if random.random() > 0.05 else dim + 1)]]
        doc["hermite"] = random.choice([[[corner(), corner()], [corner(), corner()]], [[corner(), corner()]], [[corner()], [corner(), corner()]], [], 3])
    if t == "hermite_curve_surface":
        for f in ("bottom", "top", "bottom_derivative", "top_derivative"):
            if random.random() < 0.9: doc[f] = curve(1) if random.random() < 0.5 else {"type": random.choice(["line", "circle"]), "from": pt(3), "to": pt(3)} if random.random() < 0.5 else {"type": "circle"}
    if t == "loft":
        doc["sections"] = random.choice([[curve(1) for _ in range(random.choice([0, 1, 2, 3, 5]))], [{"type": "circle", "radius": random.choice([1, 2, 0])} for _ in range(3)], 4])
        if random.random() < 0.5: doc["cross"] = random.choice(["bezier", "bspline", "nurbs", 1])
        if random.random() < 0.4: doc["degree_v"] = random.choice([0, 1, 2, 3, 9, -1, 1e9])
        if random.random() < 0.4: doc["parameters"] = random.choice(["uniform", "chord_length", "centripetal", "arc", [0, 1], [0, 1, 2], [2, 1, 0], [0, 0, 0], [1e300, 1e301, 1e302], 5])
    if t == "trimmed": doc.update(surface={"type":"plane"} if random.random()<0.5 else surface(1) if depth < 1 else {"type":"sphere"}, outer=curve(1))
    return doc
bad = 0
for i in range(int(sys.argv[3]) if len(sys.argv) > 3 else 400):
    s = random.random() < 0.5
    doc = surface() if s else curve()
    text = json.dumps(doc)
    if random.random() < 0.05: text = text[:random.randint(0, len(text))]
    k = str(random.choice([0,1,2,3,64,65]))
    args = random.choice([
        ["eval", "-", "--at", random.choice(["0.5", "0:0.5", "0.1,0.9", "nan", "-1", "1e308", "0.5:1e-320", "0:0.2:0.3", "1:1:0:0", "0:0.5:0.6", "2.5:0.1:0.1", "0:0.1:0.1,0.2:0.3"]), "--derivatives", k],
        ["eval", "-", "--samples", random.choice(["1","5","0","100"])],
        ["eval", "-", "--grid", "4,4", "--time", random.choice(["0.25", "-3", "nan", "x", "1e308"])],
        ["eval", "-", "--samples", "7", "--time", random.choice(["0.25", "1e300", "inf"])],
        ["eval", "-", "--grid", random.choice(["3,3","1,1","0,2"]), "--derivatives", random.choice(["0","2"])],
        ["refine", "-", "--insert", random.choice(["0.5","1,2,3","0.5,0.5,0.5,0.5"])],
        ["refine", "-", "--elevate", random.choice(["1","3","70"])],
        ["refine", "-", "--remove", "0.5"],
        ["tessellate", "-", "-o", SVG],
        ["tessellate", "-", "-o", random.choice([OBJ, STL, GLB]), "--density", random.choice(["4", "0", "100000"])],
        ["subdivide-surface", "-", "--scheme", random.choice(["catmull-clark", "doo-sabin"]), "--steps", random.choice(["1", "2", "11"]), "-o", OBJ],
        ["render", "-", "-o", PNG, "--size", random.choice(["48x32", "0x10", "9000x9000", "abc"])],
        ["fit", "-", "--degree", "3", "--control-points", "4", "--samples", "50"],
    ])
    try:
        r = subprocess.run([B] + args, input=text, capture_output=True, text=True, timeout=20)
    except subprocess.TimeoutExpired:
        print("TIMEOUT", args, text[:300]); bad += 1; continue
    err = r.stderr.strip()
    ok = (r.returncode == 0 and (r.stdout or args[0] in ("tessellate", "render"))) or (r.returncode == 2 and len(err.splitlines()) == 1 and not r.stdout)
    if not ok or "panicked" in err or "internal error" in err:
        bad += 1
        print("BAD", r.returncode, args, text[:400], "->", err[:300], r.stdout[:100])
print(f"fuzz: {bad} bad outcomes")
shutil.rmtree(TMP, ignore_errors=True)
sys.exit(1 if bad else 0)
