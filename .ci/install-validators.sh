#!/usr/bin/env bash
# The outside judges of splinekit's exports, installed into tools/validate/ (ignored by git):
# the Khronos glTF validator (npm `gltf-validator`, pinned by package-lock.json) in
# node_modules/, and trimesh with numpy (pinned by requirements.txt) in a Python venv .venv/.
# Idempotent: does nothing when the pinned versions are already there.
set -euo pipefail
cd "$(dirname "$0")/../tools/validate"

SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO=sudo; fi
need_debian=()
command -v npm >/dev/null 2>&1 || need_debian+=(nodejs npm)
python3 -c "import venv, ensurepip" >/dev/null 2>&1 || need_debian+=(python3-venv)
if [ ${#need_debian[@]} -gt 0 ]; then
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${need_debian[@]}"
fi

pinned=$(node -p "require('./package.json').dependencies['gltf-validator']")
installed=$(node -p "try { require('./node_modules/gltf-validator/package.json').version } catch (e) { '' }")
if [ "$installed" = "$pinned" ]; then
    echo "validators: gltf-validator $installed present"
else
    npm ci --no-audit --no-fund --loglevel=error
fi

stamp=.venv/splinekit-requirements.txt
if [ -x .venv/bin/python ] && cmp -s requirements.txt "$stamp"; then
    echo "validators: $(tr '\n' ' ' < requirements.txt)present"
else
    rm -rf .venv
    python3 -m venv .venv
    .venv/bin/pip install --quiet --disable-pip-version-check -r requirements.txt
    cp requirements.txt "$stamp"
fi
