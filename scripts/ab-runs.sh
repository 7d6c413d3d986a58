#!/usr/bin/env bash
# Compares two builds on one model in fresh forked children, alternating them run by run so that
# a change of machine load hits both alike (BENCHMARKS.md quotes these medians).
# Usage: scripts/ab-runs.sh BIN_A BIN_B MODEL SIZE_PERCENT [RUNS]
#   BIN_A, BIN_B: two builds of bench_forked_runs (bench/bench_forked_runs.cpp), e.g. from a
#   worktree at the commit before and from this one.
set -euo pipefail
[[ $# -ge 4 ]] || { echo "usage: $0 BIN_A BIN_B MODEL SIZE_PERCENT [RUNS]" >&2; exit 2; }
a=$1 b=$2 model=$3 size=$4 runs=${5:-10}
for _ in $(seq "$runs"); do
  for bin in "$a" "$b"; do
    "$bin" "$model" "$size" 1 | sed -n "s|^run 1: .*user=\([0-9.]*\) s system=\([0-9.]*\) s.*|$bin \1 \2|p"
  done
done | python3 -c '
import statistics, sys
runs = {}
for line in sys.stdin:
    name, user, system = line.split()
    runs.setdefault(name, []).append((float(user), float(system)))
for name, r in runs.items():
    total = [u + s for u, s in r]
    print(f"{name}: median cpu {statistics.median(total):.4f} s (min {min(total):.4f}), "
          f"median system {statistics.median([s for _, s in r]):.4f} s, {len(r)} runs")
'
