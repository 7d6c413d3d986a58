#!/usr/bin/env bash
# README command 1: install what is missing, build the delpsc command, run the main job.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DDELPSC_BUILD_TESTS=OFF -DDELPSC_BUILD_BENCH=OFF >/dev/null
cmake --build build -j"$(nproc)" --target delpsc_app
# Main job until the mesher lands: the regular triangulation of 200k weighted points, checked,
# with 2000 vertex removals (figures printed as key=value lines).
build/bin/delpsc triangulate --generate weighted:200000 --check --remove 2000
