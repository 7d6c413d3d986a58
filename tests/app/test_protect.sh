#!/usr/bin/env bash
# delpsc protect: a cube and a 10-degree wedge written by hand, the report, the --balls text file
# read back, the VTU, --check, sizes as lengths and percentages, and bad input.
source "$(dirname "$0")/lib.sh"

write_cube "$TMP/cube.off"

# A prism over a triangle with a 10-degree apex (legs of length 1), height 1/2.
cat >"$TMP/wedge.off" <<'MODEL'
OFF
6 8 0
0 0 0
0.9961946980917455 -0.08715574274765817 0
0.9961946980917455 0.08715574274765817 0
0 0 0.5
0.9961946980917455 -0.08715574274765817 0.5
0.9961946980917455 0.08715574274765817 0.5
3 0 2 1
3 3 4 5
3 0 1 4
3 0 4 3
3 1 2 5
3 1 5 4
3 2 0 3
3 2 3 5
MODEL

# check_balls_file FILE: the --balls text agrees with the report (balls, corner_balls) and is
# well formed: every corner line has 5 numbers, every curve block announces N ball lines.
check_balls_file() {
  awk -v balls="$(value balls)" -v corners="$(value corner_balls)" '
    $1 == "corner" { if (NF != 6) bad = "corner line with " NF " fields"; ncorner++; next }
    $1 == "curve"  { if (NF != 5) bad = "curve line with " NF " fields"; expect += $5; ncurve++; next }
    NF == 4 { nball++; if ($4 <= 0) bad = "radius " $4; next }
    { bad = "unexpected line: " $0 }
    END {
      if (bad != "") { print bad; exit 1 }
      if (ncorner != corners) { print "corner lines " ncorner " != corner_balls " corners; exit 1 }
      if (nball != expect) { print "ball lines " nball " != announced " expect; exit 1 }
      if (nball + ncorner != balls) { print "balls " nball + ncorner " != reported " balls; exit 1 }
    }' "$1"
}

expect 0 "" -- protect "$TMP/cube.off" --size 0.1 --balls "$TMP/cube-balls.txt" -o "$TMP/cube-balls.vtu" --check
[[ "$(value valid)" == "true" ]] || fail "cube balls not valid"
[[ "$(value corners)" == "8" && "$(value corner_balls)" == "8" ]] || fail "cube corner balls: $(value corner_balls)"
[[ "$(value curves)" == "12" ]] || fail "cube curves: $(value curves)"
[[ "$(value lambda)" == "0.1" ]] || fail "absolute size: lambda=$(value lambda)"
awk -v r="$(value max_radius)" 'BEGIN { exit !(r > 0 && r <= 0.1) }' || fail "max_radius $(value max_radius) above 0.1"
awk -v lo="$(value min_radius)" -v hi="$(value max_radius)" 'BEGIN { exit !(lo > 0 && lo <= hi) }' \
  || fail "radii min=$(value min_radius) max=$(value max_radius)"
[[ "$(value balls)" -gt 8 ]] || fail "too few balls: $(value balls)"
msg=$(check_balls_file "$TMP/cube-balls.txt") || fail "cube --balls file: $msg"
[[ $(grep -c '^curve ' "$TMP/cube-balls.txt") -eq 12 ]] || fail "cube --balls file: not 12 curve blocks"
grep -q "NumberOfPoints=\"$(value balls)\"" "$TMP/cube-balls.vtu" || fail "VTU does not hold $(value balls) points"
grep -q 'Name="radius"' "$TMP/cube-balls.vtu" || fail "VTU lacks the radius array"

# A percentage of the bounding-box diagonal (sqrt 3 for the unit cube); smaller sizes, more balls.
expect 0 "" -- protect "$TMP/cube.off" --size 1%
awk -v l="$(value lambda)" 'BEGIN { exit !(l > 0.017320 && l < 0.017321) }' || fail "1% of sqrt(3): lambda=$(value lambda)"
coarse=$(value balls)
expect 0 "" -- protect "$TMP/cube.off" --size 0.25% --check
[[ "$(value valid)" == "true" ]] || fail "cube at 0.25% not valid"
[[ "$(value balls)" -gt "$coarse" ]] || fail "0.25% gave $(value balls) balls, not more than 1% ($coarse)"

# The small angle: terminates, valid, and needs balls far below λ near the apex.
for size in 4% 1% 0.25%; do
  expect 0 "" -- protect "$TMP/wedge.off" --size "$size" --check --balls "$TMP/wedge-balls.txt"
  [[ "$(value valid)" == "true" ]] || fail "wedge at $size not valid"
  msg=$(check_balls_file "$TMP/wedge-balls.txt") || fail "wedge --balls file at $size: $msg"
  awk -v lo="$(value min_radius)" -v l="$(value lambda)" 'BEGIN { exit !(lo < l / 4) }' \
    || fail "wedge at $size: smallest ball $(value min_radius) not well below lambda $(value lambda)"
done

# Above 90 degrees no cube edge is a feature: nothing to protect.
expect 0 "" -- protect "$TMP/cube.off" --size 1% --angle 95 --balls "$TMP/none.txt"
[[ "$(value balls)" == "0" && "$(value curves)" == "0" ]] || fail "no features: balls=$(value balls)"
[[ ! -s "$TMP/none.txt" ]] || fail "no features: the balls file is not empty"

expect 2 "cannot open" -- protect "$TMP/missing.off" --size 1%
printf 'this is not a model' >"$TMP/garbage.stl"
expect 2 "garbage.stl" -- protect "$TMP/garbage.stl" --size 1%
for bad in abc -1 0 % 1%% 1e999 nan; do
  expect 2 "--size" -- protect "$TMP/cube.off" --size "$bad"
done
expect 2 "" -- protect "$TMP/cube.off"
expect 2 "" -- protect "$TMP/cube.off" --size 1% --angle 200
expect 2 ".vtu" -- protect "$TMP/cube.off" --size 1% -o "$TMP/balls.txt"
expect 2 "--balls $TMP/no/such/dir/balls.txt: no such directory" -- protect "$TMP/cube.off" --size 1% --balls "$TMP/no/such/dir/balls.txt"
write_crossing "$TMP/crossing.off"
expect 2 "intersects itself: triangles 0 and 1" -- protect "$TMP/crossing.off" --size 1%
# A size the job could never finish at is refused at once, not after minutes at a cap.
expect 2 "is too small for this model" -- protect "$TMP/cube.off" --size 1e-7%
expect 2 "--report $TMP/b.txt: the same file as --balls $TMP/b.txt" -- \
  protect "$TMP/cube.off" --size 10% --balls "$TMP/b.txt" --report "$TMP/b.txt"
[[ ! -e "$TMP/b.txt" ]] || fail "--balls and --report naming one file: a file was written"
# --max-seconds stops Protect between its ball edits (0.001% needs ~880,000 balls, ~3.5 s here):
# exit 1, the balls reached so far named, nothing written. (A limit passed before Protect starts
# gives another message; at 0.3 s this test failed once while the suite shared the machine with
# two long meshing runs - not reproduced since: 1 s leaves room.)
expect 1 "protection stopped on request with" -- protect "$TMP/cube.off" --size 0.001% --max-seconds 1 --balls "$TMP/timed.txt"
[[ ! -e "$TMP/timed.txt" ]] || fail "--max-seconds: balls written after the stop"
expect 2 "NaN" -- protect "$TMP/cube.off" --size 1% --max-seconds nan

# A model far from the origin is protected next to it (io/model_frame.h); the balls' centres are
# written in its own frame, the corners' exactly at its corners.
write_far_cube "$TMP/far.off"
expect 0 "" -- protect "$TMP/far.off" --size 0.1 --balls "$TMP/far-balls.txt" -o "$TMP/far-balls.vtu" --check
[[ "$(value valid)" == "true" && "$(value corner_balls)" == "8" ]] || fail "far cube: valid=$(value valid) corner_balls=$(value corner_balls)"
in_far_cube "$TMP/far-balls.txt" && in_far_cube "$TMP/far-balls.vtu" || fail "far cube: ball centres not in the model's frame"
grep -q "^corner 6 1000000001 2000000001 -2999999999 " "$TMP/far-balls.txt" || fail "far cube: corner 6 not at its vertex"
# Output paths are checked before Protect, as mesh checks its own: no figures, no file.
expect 2 "-o $TMP/no-such-dir/b.vtu: no such directory" -- protect "$TMP/cube.off" --size 5% -o "$TMP/no-such-dir/b.vtu"
[[ ! -s "$TMP/out" ]] || fail "protect with an unwritable -o printed figures: $(head -c 200 "$TMP/out")"
finish
