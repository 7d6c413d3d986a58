#!/usr/bin/env bash
# Fetches the polygon models of Debian's libcgal-demo package (fandisk, part, anchor, joint,
# elephant, ...) into data/cgal-demo/, which is gitignored: the models are CGAL's, not ours, and
# are only read by tests and benchmarks (a test missing one fails unless
# DELPSC_ALLOW_MISSING_CGAL_DATA is set: tests/support/cgal_demo_data.h).
#
# Uses `apt-get download` (no root needed, nothing installed) into a temporary directory, then
# takes data/meshes/*.off out of usr/share/doc/libcgal-dev/data.tar.gz inside the package.
# Usage: scripts/get-cgal-data.sh [MODEL...]   (default: the models the tests use)
#        scripts/get-cgal-data.sh --all         (every .off/.ply/.stl/.obj of data/meshes, into
#                                               data/cgal-demo/all/, for scripts/sweep-models.sh)
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
dest="$root/data/cgal-demo"
all=0
if [ "${1:-}" = "--all" ]; then all=1; shift; fi
models=("$@")
if [ ${#models[@]} -eq 0 ]; then
  models=(fandisk part anchor joint elephant cube sphere helmet triceratops boeing cheese dino hand mpi mpi_triang
          elephant-with-holes armadillo femur)
fi

missing=$all
[ "$all" -eq 1 ] && [ -n "$(ls -A "$dest/all" 2>/dev/null)" ] && missing=0
if [ "$all" -eq 0 ]; then
  for m in "${models[@]}"; do [ -s "$dest/$m.off" ] || missing=1; done
fi
if [ "$missing" -eq 0 ]; then exit 0; fi

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
# apt-get download writes into the current directory; _apt may not be able to write to a
# private temporary directory, which only produces a warning.
apt-get download libcgal-demo
deb=$(ls libcgal-demo_*.deb)
data_member=$(ar t "$deb" | grep '^data\.tar')
ar x "$deb" "$data_member"
inner=./usr/share/doc/libcgal-dev/data.tar.gz
tar xf "$data_member" "$inner"

mkdir -p "$dest"
if [ "$all" -eq 1 ]; then
  mkdir -p "$dest/all"
  tar xzf "$inner" -C "$tmp" data/meshes
  find "$tmp/data/meshes" -maxdepth 1 -type f \( -name '*.off' -o -name '*.ply' -o -name '*.stl' -o -name '*.obj' \) \
    -exec cp {} "$dest/all/" \;
  echo "data/cgal-demo/all/: $(ls "$dest/all" | wc -l) models"
  exit 0
fi
for m in "${models[@]}"; do
  tar xzf "$inner" -O "data/meshes/$m.off" > "$dest/$m.off"
  echo "data/cgal-demo/$m.off ($(wc -c < "$dest/$m.off") bytes)"
done
