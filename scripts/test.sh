#!/usr/bin/env bash
# README command 2: install what is missing, build everything with warnings as errors, run every
# test through ctest (the CGAL cross-checks included). .ci/run calls exactly this.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh --cgal
# Real models from Debian's libcgal-demo (not committed), which the real-model tests need.
bash scripts/require-cgal-data.sh
jobs=$(nproc)
cmake -S . -B build-test -DCMAKE_BUILD_TYPE=Release -DDELPSC_WERROR=ON -DDELPSC_WITH_CGAL=ON >/dev/null
cmake --build build-test -j"$jobs"
ctest --test-dir build-test --output-on-failure -j"$jobs"
