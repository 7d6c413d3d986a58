#!/usr/bin/env bash
# README command 1: install what is missing, build the delpsc command, run the main job.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DDELPSC_BUILD_TESTS=OFF -DDELPSC_BUILD_BENCH=OFF >/dev/null
cmake --build build -j"$(nproc)" --target delpsc_app
# The main job: mesh the sample part the project ships (samples/part.off, made by
# tools/make_sample_part) at 2% of its diagonal and check G1; write the mesh (Medit, patches and
# curves labelled), the report as JSON and a picture of the mesh, then a VTU for ParaView and a
# picture of the features found. Figures as key=value lines.
mkdir -p out
build/bin/delpsc mesh samples/part.off -o out/part.mesh --size 2% --check --report out/part.json --preview out/part.svg
build/bin/delpsc mesh samples/part.off -o out/part.vtu --size 2% -q >/dev/null
build/bin/delpsc features samples/part.off --preview out/part-features.svg >/dev/null
echo "wrote out/part.mesh (the mesh), out/part.json (the report), out/part.svg (the picture)," \
  "out/part.vtu (for ParaView), out/part-features.svg (the features)"
