#!/usr/bin/env bash
# delpsc features: counts on a cube written by hand, outputs, and bad input.
source "$(dirname "$0")/lib.sh"

write_cube "$TMP/cube.off"
expect 0 "" -- features "$TMP/cube.off" -o "$TMP/cube.vtu"
[[ "$(value corners)" == "8" ]] || fail "cube corners: $(value corners)"
[[ "$(value curves)" == "12" ]] || fail "cube curves: $(value curves)"
[[ "$(value patches)" == "6" ]] || fail "cube patches: $(value patches)"
grep -q "UnstructuredGrid" "$TMP/cube.vtu" || fail "no VTU written"
# Above 90 degrees no cube edge is sharp: one closed patch, no curves.
expect 0 "" -- features "$TMP/cube.off" --angle 95 -o "$TMP/cube.mesh"
[[ "$(value curves)" == "0" && "$(value patches)" == "1" && "$(value patches_without_boundary)" == "1" ]] \
  || fail "cube at 95 degrees: curves=$(value curves) patches=$(value patches)"
grep -q "Triangles" "$TMP/cube.mesh" || fail "no Medit mesh written"

expect 2 "cannot open" -- features "$TMP/missing.off"
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n' >"$TMP/truncated.off"
expect 2 "truncated.off" -- features "$TMP/truncated.off"
printf 'this is not a model' >"$TMP/garbage.stl"
expect 2 "garbage.stl" -- features "$TMP/garbage.stl"
expect 2 "" -- features "$TMP/cube.off" --angle 200
expect 2 "unknown output format" -- features "$TMP/cube.off" -o "$TMP/out.xyz"
expect 2 "" -- features
# --preview draws the complex: one polygon per triangle seen (the closed cube's back half, 6 of
# its 12 triangles, is left out), one line per feature-edge segment.
expect 0 "" -- features "$TMP/cube.off" --preview "$TMP/cube.svg"
[[ "$(grep -c '<polygon' "$TMP/cube.svg")" == "6" ]] || fail "preview polygons: $(grep -c '<polygon' "$TMP/cube.svg")"
[[ "$(grep -c '<line' "$TMP/cube.svg")" == "12" ]] || fail "preview lines: $(grep -c '<line' "$TMP/cube.svg")"
grep -q "8 corners, 12 curves, 6 patches" "$TMP/cube.svg" || fail "preview title lacks the counts"
expect 2 "SVG" -- features "$TMP/cube.off" --preview "$TMP/cube.png"
expect 2 "no such directory" -- features "$TMP/cube.off" --preview "$TMP/no-such-dir/cube.svg"
write_crossing "$TMP/crossing.off"
expect 2 "intersects itself: triangles 0 and 1" -- features "$TMP/crossing.off"
finish
