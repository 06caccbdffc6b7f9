#!/usr/bin/env bash
# Installs the outside readers the export tests check files with (gltf-validator, three.js,
# tinyusdz: pinned in tests/readers/package.json and package-lock.json) into
# tests/readers/node_modules, when they are missing or the lock file changed. node and npm come
# from Debian (scripts/install-deps.sh). The tests that need a reader skip visibly without it.
set -euo pipefail
cd "$(dirname "$0")/../tests/readers"
if ! command -v npm >/dev/null; then
  echo "warning: npm not found: the reader tests (ctest -L readers) will be skipped" >&2
  exit 0
fi
stamp=node_modules/.package-lock.json
if [[ -f "$stamp" && "$stamp" -nt package-lock.json ]]; then
  exit 0
fi
echo "Installing the test readers (npm ci in tests/readers)"
npm ci --no-audit --no-fund --loglevel=error
