#!/usr/bin/env bash
# Every test under AddressSanitizer and UndefinedBehaviorSanitizer (-DDELPSC_SANITIZE=ON): out-of-
# bounds and use-after-free reads, leaks, signed overflow, misaligned or null accesses, bad
# shifts and casts anywhere in the library, the command or the tests abort the test that drove
# them. Its own build directory (build-sanitize), -O1 with assertions on, no CGAL cross-checks
# (CGAL's headers are slow to build instrumented and are not our code), no -Werror (GCC 12 warns
# falsely inside libstdc++ under the sanitizers). About 10 minutes of building and 15 of testing
# on two cores (session 18: all 70 tests passed).
# Usage: scripts/sanitize.sh [ctest arguments, e.g. -R refine]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/require-cgal-data.sh
jobs=$(nproc)
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
  -DDELPSC_SANITIZE=ON -DDELPSC_BUILD_BENCH=OFF -DDELPSC_WITH_CGAL=OFF >/dev/null
cmake --build build-sanitize -j"$jobs"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build-sanitize --output-on-failure -j"$jobs" --timeout 1800 "$@"
