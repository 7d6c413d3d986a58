#!/usr/bin/env bash
# Meshes every model of a directory with `delpsc mesh --check` and prints one tab-separated line
# per model: name, exit code, wall seconds, vertices, disk_condition, g1, topology_ok,
# patches_topology_ok, min_angle, the last line of stderr; then, on stderr, how many models ended
# with each exit code (124: the timeout). A robustness sweep: every model should end within the
# timeout with a mesh that passes the checks (0) or a clear error (2), never a crash or a hang.
# Usage: scripts/sweep-models.sh [DIR] [SIZE] [TIMEOUT_SECONDS] [DELPSC]
#   defaults: data/cgal-demo/all (scripts/get-cgal-data.sh --all), 2%, 120, build/bin/delpsc
set -uo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
dir=${1:-$root/data/cgal-demo/all}
size=${2:-2%}
limit=${3:-120}
delpsc=${4:-$root/build/bin/delpsc}
if [ "$dir" = "$root/data/cgal-demo/all" ]; then "$root/scripts/get-cgal-data.sh" --all >&2 || exit 2; fi
[ -x "$delpsc" ] || { echo "sweep-models.sh: no delpsc binary at $delpsc (build first)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

declare -A codes=()
for model in "$dir"/*; do
  [ -f "$model" ] || continue
  start=$(date +%s%N)
  timeout "$limit" "$delpsc" mesh "$model" --size "$size" --check -o "$tmp/out.mesh" >"$tmp/stdout" 2>"$tmp/stderr"
  code=$?
  ms=$(( ($(date +%s%N) - start) / 1000000 ))
  value() { sed -n "s/^$1=//p" "$tmp/stdout" | head -n 1; }
  printf '%s\t%s\t%d.%02d\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$(basename "$model")" "$code" $((ms / 1000)) $((ms % 1000 / 10)) \
    "$(value vertices)" "$(value disk_condition)" "$(value g1)" "$(value topology_ok)" \
    "$(value patches_topology_ok)" "$(value min_angle)" "$(grep -v '^\s*$' "$tmp/stderr" | tail -n 1 | cut -c1-800)"
  codes[$code]=$(( ${codes[$code]:-0} + 1 ))
done
echo "--- exit codes at --size $size (timeout $limit s):" >&2
for code in "${!codes[@]}"; do echo "  exit $code: ${codes[$code]} model(s)" >&2; done
