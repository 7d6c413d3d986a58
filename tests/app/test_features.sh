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
# -o too is checked before the work, and nothing is printed for a run that cannot write.
expect 2 "-o $TMP/no-such-dir/f.vtu: no such directory" -- features "$TMP/cube.off" -o "$TMP/no-such-dir/f.vtu"
[[ ! -s "$TMP/out" ]] || fail "features with an unwritable -o printed figures: $(head -c 200 "$TMP/out")"
# A flat cap: triangle 1 (0, 2, 4) rises 1e-7 above the sheet's diagonal (angles of 1.4e-7 rad at
# its ends). Healed, the sheet stays one flat patch with its 4 boundary curves, and the command
# says so on stderr (not under -q); kept, it would stand upright with three sharp edges.
printf 'OFF\n5 4 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1e-7\n3 0 1 2\n3 0 2 4\n3 4 2 3\n3 0 4 3\n' >"$TMP/flat-cap.off"
expect 0 "1 nearly flat triangle(s)" -- features "$TMP/flat-cap.off"
[[ "$(value flat_caps)" == "1" && "$(value patches)" == "1" && "$(value curves)" == "4" ]] \
  || fail "flat cap: flat_caps=$(value flat_caps) patches=$(value patches) curves=$(value curves)"
expect 0 "" -- -q features "$TMP/flat-cap.off"
if grep -q "flat triangle" "$TMP/err"; then fail "-q still warns of the flat cap"; else pass; fi
write_crossing "$TMP/crossing.off"
expect 2 "intersects itself: triangles 0 and 1" -- features "$TMP/crossing.off"

# A model far from the origin: its complex is computed next to it and written in its own frame.
write_far_cube "$TMP/far.off"
expect 0 "" -- features "$TMP/far.off" -o "$TMP/far.mesh"
[[ "$(value corners)" == "8" && "$(value curves)" == "12" && "$(value patches)" == "6" ]] || fail "far cube's complex"
in_far_cube "$TMP/far.mesh" || fail "far cube: features' mesh not in the model's frame"
finish
