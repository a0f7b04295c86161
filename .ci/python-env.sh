#!/usr/bin/env bash
# Creates the Python virtual environment of the test oracles at target/ci-venv from
# .ci/requirements.txt. Idempotent: does nothing when the venv already holds exactly the
# pinned requirements (a stamp file records the requirements it was built from).
# Prints the venv's python path on the last line.
set -euo pipefail
cd "$(dirname "$0")/.."
venv=target/ci-venv
stamp="$venv/.requirements"
if [ -x "$venv/bin/python" ] && [ -f "$stamp" ] && cmp -s .ci/requirements.txt "$stamp"; then
    echo "$venv/bin/python"
    exit 0
fi
rm -rf "$venv"
python3 -m venv "$venv"
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check --upgrade pip >&2
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check -r .ci/requirements.txt >&2
cp .ci/requirements.txt "$stamp"
echo "$venv/bin/python"
