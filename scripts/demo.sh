#!/usr/bin/env bash
# README command 1: install what is missing, build the delpsc command, run the main job.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DDELPSC_BUILD_TESTS=OFF -DDELPSC_BUILD_BENCH=OFF >/dev/null
cmake --build build -j"$(nproc)" --target delpsc_app
# The main job: mesh the sample part the project ships (samples/part.off, made by
# tools/make_sample_part) at 2% of its diagonal, check G1, write the mesh (Medit, patches and
# curves labelled) and a VTU for ParaView, and draw its features; figures as key=value lines.
mkdir -p out
build/bin/delpsc mesh samples/part.off -o out/part.mesh --size 2% --check
build/bin/delpsc mesh samples/part.off -o out/part.vtu --size 2% -q >/dev/null
build/bin/delpsc features samples/part.off --preview out/part-features.svg >/dev/null
echo "wrote out/part.mesh, out/part.vtu, out/part-features.svg"
