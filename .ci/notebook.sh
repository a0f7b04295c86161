#!/usr/bin/env bash
# The tour notebook (docs/tour.ipynb) as a reader sees it: executed by nbclient in VENV (a
# venv with splinekit installed — .ci/python.sh passes its fresh venv, holding the debug
# build with the `render` feature, so that every view also carries its PNG picture),
# exported to HTML by nbconvert, and opened from file:// in the headless Chromium of the
# gallery's browser test (tools/browser/notebook_test.mjs): every 3-D view must load
# without console errors and draw something, the animated one play and pause. The executed
# notebook, the page and the screenshots go to target/notebook/. Usage:
#   .ci/notebook.sh VENV
set -euo pipefail
cd "$(dirname "$0")/.."
venv="${1:?usage: .ci/notebook.sh VENV}"
started=$SECONDS
# shellcheck disable=SC2046 # the pinned packages, one word each
"$venv/bin/pip" install --quiet --disable-pip-version-check $(bash .ci/install-python.sh --notebook-packages)
out=target/notebook
rm -rf "$out"
mkdir -p "$out"
# Executed where a reader opens it (docs/), without touching the committed file.
(cd docs && "$venv/bin/python" - "$(pwd)/../$out/tour.ipynb" <<'PY'
import sys
import nbformat
from nbclient import NotebookClient

nb = nbformat.read("tour.ipynb", as_version=4)
NotebookClient(nb, timeout=600, kernel_name="python3", resources={"metadata": {"path": "."}}).execute()
errors = [o for c in nb.cells for o in c.get("outputs", []) if o.get("output_type") == "error"]
stderr = [o["text"] for c in nb.cells for o in c.get("outputs", []) if o.get("name") == "stderr"]
if errors or stderr:
    sys.exit(f"tour.ipynb: {len(errors)} cells failed, stderr: {stderr}")
views = sum("splinekit-view" in o.get("data", {}).get("text/html", "") for c in nb.cells for o in c.get("outputs", []))
pictures = sum("image/png" in o.get("data", {}) for c in nb.cells for o in c.get("outputs", []))
nbformat.write(nb, sys.argv[1])
print(f"tour.ipynb executed: {views} views, {pictures} PNG pictures")
PY
)
# Without the CDN scripts of nbconvert's template (require.js, MathJax): the page works offline.
"$venv/bin/python" -m nbconvert --to html --template-file tools/notebook/offline.html.j2 --output-dir "$out" \
    "$out/tour.ipynb" --log-level WARN
ls -l "$out/tour.html"
bash .ci/install-browser.sh
node tools/browser/notebook_test.mjs "$out/tour.html" --out "$out/browser"
echo "notebook: $((SECONDS - started)) s"
