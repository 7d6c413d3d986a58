#!/usr/bin/env bash
# Redraws the README's pictures of the sample part with our own code: docs/sample-features.svg
# (delpsc features --preview) and docs/sample-mesh.svg (delpsc mesh --preview, λ = 2%, the README's
# quick tour), and prints the lines of the report the tour quotes. Uses build/bin/delpsc (scripts/demo.sh
# builds it) or the binary named by $DELPSC.
set -euo pipefail
cd "$(dirname "$0")/.."
delpsc=${DELPSC:-build/bin/delpsc}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$delpsc" features samples/part.off --preview docs/sample-features.svg >/dev/null
"$delpsc" mesh samples/part.off -o "$tmp/part.mesh" --size 2% --check --preview docs/sample-mesh.svg -q >"$tmp/report"
echo "wrote docs/sample-features.svg, docs/sample-mesh.svg; the README's report excerpt:" >&2
grep -E '^(vertices|triangles|patches|curves|corners|balls|seconds|disk_condition|min_angle|radius_edge_ratio|hausdorff|patches_manifold|patches_topology_ok|topology_ok|g1)=' "$tmp/report"
