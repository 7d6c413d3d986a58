#!/usr/bin/env bash
# Issue 6's comparison with CGAL Mesh_3 (BENCHMARKS.md, "Meshing end to end vs CGAL Mesh_3"):
# builds bench/cgal/bench_mesh_vs_cgal.cpp with CGAL in a Release build directory, fetches the
# libcgal-demo models, and prints the Markdown table.
# Usage: scripts/bench-vs-cgal.sh [--models a,b] [--sizes 2,1,0.5] [--repetitions N] [--cap S]
#        [--delpsc-criteria size|cgal] [--match-vertices yes|no]
# Environment: BUILD_DIR (default build-cgalbench), JOBS (default 2).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build-cgalbench}
models=(fandisk part anchor joint cube elephant sphere)
bash scripts/get-cgal-data.sh "${models[@]}" >/dev/null
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DDELPSC_WITH_CGAL=ON -DDELPSC_BUILD_BENCH=ON >/dev/null
cmake --build "$build" -j"${JOBS:-2}" --target cgal_bench_mesh_vs_cgal
echo "# $(date -u +%F), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg), commit $(git rev-parse --short HEAD 2>/dev/null || echo '?')"
"$build/bin/cgal_bench_mesh_vs_cgal" --data data/cgal-demo "$@"
