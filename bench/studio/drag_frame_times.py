#!/usr/bin/env python3
"""Whole frame times of the studio window during a drag, as a person drags (issue 11).

Run under an X server with xdotool, e.g.

    cargo build --release -p splinekit-cli
    xvfb-run -a -s "-screen 0 1280x800x24" python3 bench/studio/drag_frame_times.py \
        examples/scenes/blending_torus_local_patches.json local_patch 3,4

It opens the document in a 1280x800 window (`--report-handles`, `--report-frame-times`),
waits for the handles, drags the handle of the given kind and index (`local_patch k,l`,
`local_curve k`) by 120 x 80 pixels in 40 steps, closes the window and prints the median
and quartiles of the frames drawn during the drag: the whole frame's work (panels, the
3-D view's composition and drawing, egui's painting and presenting) and of it the 3-D
view, the panels' layout, egui's tessellation and painting and the present; and the
process's CPU time a drag frame (all threads, llvmpipe's included: it depends much less on
the machine's load than the wall times). With `SPLINEKIT_FRAME_STAGES=1` the window waits
for the device after the 3-D view and after egui's painting, so that the stages do not
overlap and each time is its own. The window draws only when something changes, so the frames between the button
going down and up are the drag's.
"""

import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

BIN = os.environ.get("SPLINEKIT", "target/release/splinekit")


def xdotool(*args):
    return subprocess.run(["xdotool", *args], check=True, capture_output=True, text=True).stdout.strip()


def wait_for(path, ready, timeout):
    """The report at `path` once `ready` accepts it, or None after `timeout` seconds; the
    last report read comes back too (to say what the window did show)."""
    start, last = time.time(), None
    while time.time() - start < timeout:
        try:
            with open(path) as f:
                last = json.load(f)
            if ready(last):
                return last, last
        except (OSError, ValueError):
            pass
        time.sleep(0.1)
    return None, last


def cpu_seconds(pid):
    """User and system CPU seconds of process `pid` so far, all its threads (/proc)."""
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def shown(report):
    """The handles a report lists, as `kind index` (kinds with their index ranges)."""
    if report is None:
        return "no handle report at all (the window did not draw a frame)"
    kinds = {}
    for h in report.get("handles", []):
        kinds.setdefault(h["kind"], []).append(h["index"])
    if not kinds:
        return "no handles (is the object drawn with local_pieces or control_net?)"
    return "; ".join(f"{k}: {len(v)} handles, first {v[0]}, last {v[-1]}" for k, v in kinds.items())


def main():
    with tempfile.TemporaryDirectory(prefix="splinekit-frames-") as tmp:
        measure(tmp)


def measure(tmp):
    """Opens the studio, drags one handle, and prints the frame times; reports go in `tmp`."""
    doc, kind, index = sys.argv[1], sys.argv[2], [int(x) for x in sys.argv[3].split(",")]
    steps = int(os.environ.get("STEPS", "40"))
    report, frames = os.path.join(tmp, "handles.json"), os.path.join(tmp, "frames.json")
    child = subprocess.Popen([BIN, "view", doc, "--window-size", "1280x800", "--report-handles", report,
                              "--report-frame-times", frames])
    want = index[0] if len(index) == 1 else index

    def find(v):
        return next((h for h in v.get("handles", []) if h["kind"] == kind and h["index"] == want), None)

    timeout = float(os.environ.get("HANDLE_TIMEOUT", "60"))
    found, last = wait_for(report, find, timeout)
    if found is not None:
        time.sleep(2.0)
        found, last = wait_for(report, find, timeout)
    if found is None:
        child.kill()
        child.wait()
        sys.exit(f"gave up after {timeout:.0f} s: the window shows no handle {kind} {sys.argv[3]} of {doc}; "
                 f"it shows {shown(last)}")
    h = find(found)
    window = xdotool("search", "--sync", "--name", "splinekit studio").splitlines()[0]
    xdotool("windowfocus", "--sync", window)
    x0, y0 = h["x"], h["y"]
    xdotool("mousemove", "--window", window, str(round(x0)), str(round(y0)))
    time.sleep(1.0)
    cpu0 = cpu_seconds(child.pid)
    xdotool("mousedown", "1")
    for s in range(1, steps + 1):
        f = s / steps
        xdotool("mousemove", "--window", window, str(round(x0 + 120 * f)), str(round(y0 + 80 * f)))
        time.sleep(0.25)
    xdotool("mouseup", "1")
    cpu1 = cpu_seconds(child.pid)
    time.sleep(1.0)
    xdotool("key", "ctrl+q")
    child.wait(timeout=120)
    with open(frames) as f:
        log = json.load(f)
    drag = [i for i, d in enumerate(log["dragging"]) if d]
    if len(drag) < 4:
        sys.exit(f"only {len(drag)} frames were drawn during the drag")
    stages = (("whole frame", "work_ms"), ("3-D view", "scene_ms"), ("panels (egui layout)", "panels_ms"),
              ("egui tessellation", "tessellate_ms"), ("egui painting", "paint_ms"), ("present", "present_ms"))
    for name, key in stages:
        if key not in log:
            continue
        xs = [log[key][i] for i in drag]
        q = statistics.quantiles(xs, n=4)
        print(f"{name}: median {statistics.median(xs):.1f} ms, quartiles {q[0]:.1f}-{q[2]:.1f} ms "
              f"over {len(xs)} frames")
    # Wall times grow with the machine's load; the process's CPU time (all its threads,
    # llvmpipe's raster threads included) a frame does much less.
    print(f"CPU time of the process: {1e3 * (cpu1 - cpu0) / len(drag):.1f} ms a drag frame; "
          f"load average {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
