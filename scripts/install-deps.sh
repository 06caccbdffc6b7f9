#!/usr/bin/env bash
# Installs the Debian packages Sylva needs to build, test and run — only the missing ones
# (clang, its runtime libraries and libomp build the libFuzzer harnesses of the fuzz preset).
# Uses sudo when not root. Called by ./run.sh and ./test.sh; safe to run repeatedly.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config git ccache
  qt6-base-dev qt6-base-dev-tools qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools
  libqt6opengl6-dev libgl-dev libglm-dev
  libassimp-dev assimp-utils libembree-dev libnanoflann-dev nlohmann-json3-dev libpng-dev libopenexr-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth xdotool libgl1-mesa-dri clang-format
  python3-dev pybind11-dev python3-numpy python3-pytest
  clang libclang-rt-14-dev libomp-dev
  slurmctld slurmd slurm-client munge  # tests/slurm: a one-node cluster runs a farm job
)
# node and npm for the outside readers of tests/readers (scripts/install-readers.sh): Debian's,
# unless a node with its npm is already there (NodeSource's nodejs bundles npm, and Debian's npm
# package cannot be installed beside it).
command -v node >/dev/null || PACKAGES+=(nodejs)
command -v npm >/dev/null || PACKAGES+=(npm)
# Optional extras, installed best-effort (a test that needs one skips visibly without it):
#   SYLVA_EXTRA_PACKAGES="blender python3-numpy f3d" ./test.sh
EXTRA=()
if [[ -n "${SYLVA_EXTRA_PACKAGES:-}" ]]; then
  read -r -a EXTRA <<< "${SYLVA_EXTRA_PACKAGES}"
fi

is_installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"; }
missing=()
for p in "${PACKAGES[@]}"; do is_installed "$p" || missing+=("$p"); done
missing_extra=()
for p in "${EXTRA[@]}"; do is_installed "$p" || missing_extra+=("$p"); done
if [[ ${#missing[@]} -eq 0 && ${#missing_extra[@]} -eq 0 ]]; then
  exit 0
fi

SUDO=()
if [[ $(id -u) -ne 0 ]]; then
  if command -v sudo >/dev/null; then SUDO=(sudo); else
    echo "error: need root or sudo to install: ${missing[*]}" >&2; exit 1; fi
fi
export DEBIAN_FRONTEND=noninteractive
"${SUDO[@]}" apt-get update -qq
if [[ ${#missing[@]} -gt 0 ]]; then
  echo "Installing missing Debian packages: ${missing[*]}"
  "${SUDO[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
if [[ ${#missing_extra[@]} -gt 0 ]]; then
  echo "Installing optional Debian packages: ${missing_extra[*]}"
  "${SUDO[@]}" apt-get install -y -qq --no-install-recommends "${missing_extra[@]}" ||
    echo "warning: optional packages not installed; the tests that need them will be skipped"
fi
