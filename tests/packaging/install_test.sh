#!/usr/bin/env bash
# Installs the Debian package the way a user does, resolving its Depends with apt-get, then runs
# what it installed: `sylva-cli tree` on an installed preset and `python3 -c "import sylva"`
# growing that preset (same bytes as the CLI), with Debian's python3.
#
#   install_test.sh <sylva_*.deb> --fresh-root DIR   # a fresh Debian 12 made by debootstrap
#                                                    # (minbase) in DIR: nothing else installed
#   install_test.sh <sylva_*.deb> --this-machine     # this machine (CI: a fresh Debian 12 run as
#                                                    # root); removes the package afterwards
# Needs root, and Debian's mirror for the fresh root. Prints the time of each step.
set -euo pipefail
fail() { echo "FAIL: $*" >&2; exit 1; }
[[ $# == 2 || $# == 3 ]] || fail "usage: $0 <sylva_*.deb> --fresh-root DIR | --this-machine"
deb=$(realpath "$1")
mode=$2
[[ -f $deb ]] || fail "no package $deb"
[[ $(id -u) == 0 ]] || fail "needs root (apt-get install)"
# The mirror this machine's apt uses (a CI machine may point at its own), else Debian's.
machine_mirror() {
  local uri=""
  if [[ -f /etc/apt/sources.list.d/debian.sources ]]; then
    uri=$(awk '/^URIs:/ {print $2; exit}' /etc/apt/sources.list.d/debian.sources)
  elif [[ -f /etc/apt/sources.list ]]; then
    uri=$(awk '$1 == "deb" && $0 ~ /bookworm( |$)/ {print $2; exit}' /etc/apt/sources.list)
  fi
  echo "${uri:-http://deb.debian.org/debian}"
}
mirror=${SYLVA_DEBIAN_MIRROR:-$(machine_mirror)}
start=$(date +%s)
step() { echo "install_test: $1 ($(( $(date +%s) - start )) s)"; }

# What runs inside the installed system: the CLI and the module, from /usr.
check_installed() {
  set -euo pipefail
  cd "$(mktemp -d)"
  sylva-cli tree /usr/share/sylva/presets/abop-1.24a.json --seed 3 -o cli/tree.obj --stats > stats.json
  grep -q '"vertices":[1-9]' stats.json || { echo "sylva-cli tree: $(cat stats.json)"; exit 1; }
  [[ -f cli/textures/bark.png ]] || { echo "no textures beside the export"; exit 1; }
  python3 -c "import sylva; print('import sylva', sylva.__version__, sylva.__file__)"
  python3 - <<'PY'
import os, sylva
assert sylva.__file__.startswith("/usr/lib/python3/dist-packages/"), sylva.__file__
tree = sylva.grow(os.path.join(sylva.presets_dir(), "abop-1.24a.json"), seed=3)
tree.export("py/tree.obj")
PY
  cmp cli/tree.obj py/tree.obj || { echo "module and CLI trees differ"; exit 1; }
  [[ -f /usr/share/sylva/blender/sylva_blender/__init__.py ]] || { echo "no Blender add-on"; exit 1; }
  echo "installed sylva works"
}

case $mode in
--fresh-root)
  root=${3:?--fresh-root needs a folder}
  [[ ! -e $root || -z $(ls -A "$root") ]] || fail "$root exists and is not empty"
  # A fresh root with the package's Depends is about 0.9 GB: say so up front rather than fail
  # half-way through unpacking (a CI run once did, on a disk filled by old outputs).
  parent=$(dirname "$root")
  mkdir -p "$parent"
  free_kb=$(df -Pk "$parent" | awk 'NR == 2 {print $4}')
  (( free_kb >= 2 * 1024 * 1024 )) ||
    fail "$(( free_kb / 1024 )) MB free at $parent; the fresh root needs 2 GB (0.9 GB installed, and room to unpack)"
  command -v debootstrap >/dev/null || DEBIAN_FRONTEND=noninteractive apt-get install -y -q debootstrap >/dev/null
  debootstrap --variant=minbase bookworm "$root" "$mirror" > "$root.debootstrap.log" 2>&1 ||
    { tail -20 "$root.debootstrap.log"; fail "debootstrap"; }
  step "fresh Debian 12 (debootstrap minbase) in $root, $(du -shx "$root" | cut -f1)"
  mount -t proc proc "$root/proc" || echo "install_test: warning: cannot mount /proc in the root"
  trap 'umount "$root/proc" 2>/dev/null || true' EXIT
  cp "$deb" "$root/tmp/"
  in_root() { chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root \
              DEBIAN_FRONTEND=noninteractive LANG=C.UTF-8 "$@"; }
  in_root apt-get update -q > "$root.apt.log" 2>&1 || { cat "$root.apt.log"; fail "apt-get update"; }
  in_root apt-get install -y -q --no-install-recommends "/tmp/$(basename "$deb")" >> "$root.apt.log" 2>&1 ||
    { tail -30 "$root.apt.log"; fail "apt-get install"; }
  step "apt-get install: $(grep -c '^Setting up' "$root.apt.log") packages set up, root now $(du -shx "$root" | cut -f1)"
  in_root bash -c "$(declare -f check_installed); check_installed" || fail "the installed package"
  ;;
--this-machine)
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "$deb" > apt.log 2>&1 ||
    { tail -30 apt.log; fail "apt-get install"; }
  trap 'DEBIAN_FRONTEND=noninteractive apt-get remove -y -q sylva >/dev/null 2>&1 || true' EXIT
  step "apt-get install: $(grep -c '^Setting up' apt.log) packages set up"
  env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME="${HOME:-/root}" LANG=C.UTF-8 \
    bash -c "$(declare -f check_installed); check_installed" || fail "the installed package"
  ;;
*) fail "unknown mode $mode" ;;
esac
step "package install test passed"
