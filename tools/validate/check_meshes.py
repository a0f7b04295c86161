"""Cross-checks splinekit's mesh exports with trimesh.

Reads the manifests (manifest-*.json) that the Rust test `mesh_validity` leaves beside the
files it writes, loads every file with trimesh, merges vertices at the same position (formats
that store (u, v) per vertex keep both sides of a seam as separate vertices at one place, as
glTF must), and compares with what the manifest says the surface is:

- closed: is_watertight (every edge used by exactly two faces);
- orientable: is_winding_consistent;
- closed surfaces face outward: volume > 0, and trimesh's volume and area within the
  manifest's relative tolerance of the analytic values where they are known;
- open surfaces: trimesh's area within tolerance where known.

Prints one line per file and a closing 'check_meshes: N passed, N failed' line; exits 1 on
any failure.
"""

import glob
import json
import os
import sys
import warnings

import trimesh

# trimesh divides by the (zero) volume of flat meshes for their centre of mass.
warnings.filterwarnings("ignore", category=RuntimeWarning)


def load(path):
    """The single triangle mesh of a file, exactly as stored (no processing)."""
    loaded = trimesh.load(path, process=False, file_type="stl" if path.endswith(".stla") else None)
    if isinstance(loaded, trimesh.Scene):
        geometries = list(loaded.geometry.values())
        if len(geometries) != 1:
            raise ValueError(f"expected one mesh, found {len(geometries)}")
        loaded = geometries[0]
    mesh = trimesh.Trimesh(vertices=loaded.vertices, faces=loaded.faces, process=False)
    mesh.merge_vertices(merge_tex=True, merge_norm=True)
    return mesh


def relative(value, exact):
    return abs(value / exact - 1.0)


def judge(case, path):
    mesh = load(path)
    problems = []
    closed, orientable = case["closed"], case["orientable"]
    if closed is not None and mesh.is_watertight != closed:
        problems.append(f"is_watertight {mesh.is_watertight}, expected {closed}")
    if closed is not None and mesh.is_winding_consistent != orientable:
        problems.append(f"is_winding_consistent {mesh.is_winding_consistent}, expected {orientable}")
    tolerance = case["tolerance"]
    if closed:
        if not mesh.volume > 0:
            problems.append(f"volume {mesh.volume} is not positive (faces inward)")
        if case["volume"] is not None and relative(mesh.volume, case["volume"]) > tolerance:
            problems.append(f"volume {mesh.volume} vs {case['volume']}")
    if case["area"] is not None and relative(mesh.area, case["area"]) > tolerance:
        problems.append(f"area {mesh.area} vs {case['area']}")
    line = (
        f"{os.path.basename(path):44} watertight={mesh.is_watertight!s:5} "
        f"winding_consistent={mesh.is_winding_consistent!s:5} volume={mesh.volume:.6g} area={mesh.area:.6g}"
    )
    for name, exact, value in (("volume", case["volume"], mesh.volume), ("area", case["area"], mesh.area)):
        if exact is not None and (closed or name == "area"):
            line += f" {name}_error={relative(value, exact):.2e}"
    return line, problems


def main(directory):
    manifests = sorted(glob.glob(os.path.join(directory, "manifest-*.json")))
    if not manifests:
        print(f"check_meshes: no manifest-*.json in {directory} (run the mesh_validity test first)")
        return 1
    passed = failed = 0
    for manifest in manifests:
        with open(manifest) as f:
            cases = json.load(f)["cases"]
        for case in cases:
            for name in case["files"]:
                try:
                    line, problems = judge(case, os.path.join(directory, name))
                except Exception as e:  # a file trimesh cannot read is a failure too
                    line, problems = name, [f"cannot be read: {e}"]
                print(("FAIL " if problems else "ok   ") + line)
                for p in problems:
                    print(f"       {p}")
                failed += bool(problems)
                passed += not problems
    print(f"trimesh {trimesh.__version__}")
    print(f"check_meshes: {passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "target/tmp/mesh-exports"))
