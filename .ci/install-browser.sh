#!/usr/bin/env bash
# What the gallery's browser test needs: Debian's Chromium (/usr/bin/chromium) and, in
# tools/browser/node_modules (ignored by git), the npm packages pinned by
# tools/browser/package-lock.json — playwright-core (drives the system Chromium; its own
# browser downloads are skipped), three and esbuild (to check the vendored viewer bundle).
# Idempotent: does nothing when Chromium is there and node_modules matches the lock file.
set -euo pipefail
cd "$(dirname "$0")/../tools/browser"

SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO=sudo; fi
need_debian=()
[ -x /usr/bin/chromium ] || need_debian+=(chromium)
command -v npm >/dev/null 2>&1 || need_debian+=(nodejs npm)
if [ ${#need_debian[@]} -gt 0 ]; then
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${need_debian[@]}"
fi

stamp=node_modules/.splinekit-package-lock.json
if [ -d node_modules ] && cmp -s package-lock.json "$stamp"; then
    echo "browser test: $(/usr/bin/chromium --version 2>/dev/null | head -n 1), npm packages of package-lock.json present"
else
    PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 PUPPETEER_SKIP_DOWNLOAD=1 npm ci --no-audit --no-fund --loglevel=error
    cp package-lock.json "$stamp"
fi
