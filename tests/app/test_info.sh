#!/usr/bin/env bash
# delpsc info: counts and defects of a small model with a duplicate vertex and a zero-area face.
source "$(dirname "$0")/lib.sh"

# Two triangles of a square sheet (a boundary of 4 edges), vertex 4 duplicates vertex 0, and a
# zero-area triangle (repeated index).
printf 'OFF\n5 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 0\n3 0 1 2\n3 4 2 3\n3 1 1 2\n' >"$TMP/sheet.off"
expect 0 "zero-area" -- info "$TMP/sheet.off"
[[ "$(value triangles)" == "3" ]] || fail "triangles: $(value triangles)"
[[ "$(value merged_vertices)" == "1" ]] || fail "merged_vertices: $(value merged_vertices)"
[[ "$(value unused_vertices)" == "0" ]] || fail "unused_vertices: $(value unused_vertices)"
[[ "$(value zero_area_triangles)" == "1" ]] || fail "zero_area_triangles: $(value zero_area_triangles)"
[[ "$(value boundary_edges)" == "4" ]] || fail "boundary_edges: $(value boundary_edges)"
[[ "$(value bbox)" == "0 0 0 1 1 0" ]] || fail "bbox: $(value bbox)"
[[ "$(value self_intersections)" == "0" ]] || fail "self_intersections: $(value self_intersections)"
# warnings= counts every warning line printed, not only the reader's.
printed=$(grep -c "warning" "$TMP/err")
[[ "$(value warnings)" == "$printed" && "$printed" -ge 2 ]] || fail "warnings=$(value warnings), $printed printed"
# A self-intersecting model: info counts the crossing pairs and warns, and still succeeds.
write_crossing "$TMP/crossing.off"
expect 0 "cross or overlap" -- info "$TMP/crossing.off"
[[ "$(value self_intersections)" == "1" ]] || fail "crossing: self_intersections=$(value self_intersections)"
[[ "$(value warnings)" == "$(grep -c "warning" "$TMP/err")" ]] || fail "crossing: warnings=$(value warnings)"

# A triangle listed twice (once reversed): counted as a repeat, and as a crossing pair.
printf 'OFF\n4 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n3 2 1 0\n' >"$TMP/twice.off"
expect 0 "cross or overlap" -- info "$TMP/twice.off"
[[ "$(value duplicate_triangles)" == "1" && "$(value self_intersections)" == "1" ]] \
  || fail "twice: duplicate_triangles=$(value duplicate_triangles) self_intersections=$(value self_intersections)"
# A triangle listed 100,000 times: info counts its pairs up to the cap and stops looking (it
# went through every one of the 5*10^9 pairs of copies, past any time limit).
python3 - "$TMP/copies.off" <<'PY'
import sys
n = 100000
with open(sys.argv[1], "w") as f:
    f.write(f"OFF\n4 {n + 3} 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n" + "3 0 2 1\n" * n)
PY
expect 0 "at least 100 pair(s)" -- info "$TMP/copies.off" --max-seconds 60
[[ "$(value duplicate_triangles)" == "99999" && "$(value self_intersections)" == "100" && "$(value stopped)" == "no" ]] \
  || fail "copies: duplicate_triangles=$(value duplicate_triangles) self_intersections=$(value self_intersections) stopped=$(value stopped)"
expect 0 "" -- info "$TMP/crossing.off"
[[ "$(value duplicate_triangles)" == "0" ]] || fail "crossing: duplicate_triangles=$(value duplicate_triangles)"

# --report (shared by every subcommand): the same figures as JSON.
expect 0 "" -- info "$TMP/sheet.off" --report "$TMP/info.json"
python3 -c 'import json, sys; r = json.load(open(sys.argv[1]))
sys.exit(not (r["command"] == "info" and r["triangles"] == 3 and r["bbox"] == "0 0 0 1 1 0" and r["exit_code"] == 0))' \
  "$TMP/info.json" || fail "info --report: $(cat "$TMP/info.json")"
# A file name with a quote, a backslash, a tab and a byte that is not UTF-8: valid JSON all the
# same, the bad byte as U+FFFD.
odd="$TMP/"$'q"b\\t\tx\xff.off'
cp "$TMP/sheet.off" "$odd"
expect 0 "" -- info "$odd" --report "$TMP/odd.json"
python3 -c 'import json, sys; r = json.load(open(sys.argv[1], encoding="utf-8"))
sys.exit(not r["input"].endswith("q\"b\\t\tx\ufffd.off"))' "$TMP/odd.json" || fail "info --report, odd name: $(cat "$TMP/odd.json")"

# A concave face (an L whose first corner is the reflex one) is split inside itself, not fanned
# into overlapping triangles (it was refused as a self-intersecting model); likewise in OBJ.
printf 'OFF\n6 1 0\n2 1 0\n1 1 0\n1 2 0\n0 2 0\n0 0 0\n2 0 0\n6 0 1 2 3 4 5\n' >"$TMP/ell.off"
expect 0 "" -- info "$TMP/ell.off"
[[ "$(value triangles)" == "4" && "$(value self_intersections)" == "0" ]] \
  || fail "L-shaped face: triangles=$(value triangles) self_intersections=$(value self_intersections)"
expect 0 "" -- mesh "$TMP/ell.off" --size 10% -o "$TMP/ell.mesh.off" --check
[[ "$(value g1)" == "true" ]] || fail "L-shaped face: g1=$(value g1)"
printf 'v 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nv 0 0 0\nv 2 0 0\nf 6 5 4 3 2 1\n' >"$TMP/ell.obj"
expect 0 "" -- info "$TMP/ell.obj"
[[ "$(value self_intersections)" == "0" ]] || fail "L-shaped OBJ face, clockwise: self_intersections=$(value self_intersections)"
# A binary STL whose header count is 0 (some exporters) or too low: every whole record is read,
# with a warning (0 was an 'empty model'; a low count dropped triangles).
python3 - "$TMP" <<'PY'
import struct, sys
tris = [((0, 0, 0), (0, 1, 0), (1, 0, 0)), ((0, 0, 0), (1, 0, 0), (0, 0, 1)),
        ((1, 0, 0), (0, 1, 0), (0, 0, 1)), ((0, 0, 0), (0, 0, 1), (0, 1, 0))]
for name, count in [("zero", 0), ("low", 2)]:
    with open(f"{sys.argv[1]}/{name}.stl", "wb") as f:
        f.write(b"binary".ljust(80) + struct.pack("<I", count))
        for t in tris:
            f.write(struct.pack("<12f", 0, 0, 0, *(c for v in t for c in v)) + b"\0\0")
PY
expect 0 "the header announces 0 triangles but the file holds 4 whole records" -- info "$TMP/zero.stl"
[[ "$(value triangles)" == "4" ]] || fail "zero-count STL: triangles=$(value triangles)"
expect 0 "the header announces 2 triangles" -- info "$TMP/low.stl"
[[ "$(value triangles)" == "4" ]] || fail "low-count STL: triangles=$(value triangles)"
expect 2 "cannot open" -- info "$TMP/none.ply"
printf 'ply\nformat ascii 1.0\nelement vertex 99999999999\n' >"$TMP/absurd.ply"
expect 2 "absurd.ply" -- info "$TMP/absurd.ply"
expect 2 "" -- info "$TMP/sheet.off" --angle -5

# The sharpest fold: a prism whose apex edge is 2 degrees is warned about with the edge; a cube's
# edges are 90 degrees and the flat L-shaped sheet's 180, without a warning.
printf 'OFF\n6 8 0\n0 0 0\n0.9998476952 -0.0174524064 0\n0.9998476952 0.0174524064 0\n0 0 0.5\n0.9998476952 -0.0174524064 0.5\n0.9998476952 0.0174524064 0.5\n3 0 2 1\n3 3 4 5\n3 0 1 4\n3 0 4 3\n3 1 2 5\n3 1 5 4\n3 2 0 3\n3 2 3 5\n' >"$TMP/wedge.off"
expect 0 "two triangles meet at only 2 degrees, on the edge from (0, 0, 0) to (0, 0, 0.5)" -- info "$TMP/wedge.off"
python3 -c 'import sys; sys.exit(abs(float(sys.argv[1]) - 2) > 1e-6)' "$(value sharpest_fold_degrees)" \
  || fail "wedge: sharpest_fold_degrees=$(value sharpest_fold_degrees)"
write_cube "$TMP/cube.off"
expect 0 "" -- info "$TMP/cube.off"
[[ "$(value sharpest_fold_degrees)" == "90" ]] || fail "cube: sharpest_fold_degrees=$(value sharpest_fold_degrees)"
grep -q "meet at only" "$TMP/err" && fail "cube: fold warning: $(cat "$TMP/err")"
expect 0 "" -- info "$TMP/ell.off"
[[ "$(value sharpest_fold_degrees)" == "180" ]] || fail "flat sheet: sharpest_fold_degrees=$(value sharpest_fold_degrees)"

# Vertices no triangle uses are dropped with a warning before anything takes the model's box: a
# stray one at 1e30 set info's bbox, and made the near-contact tolerance 1e21, so that mesh
# refused the cube as touching itself.
write_cube "$TMP/cube.off"
sed '2s/^8 12/10 12/; 10a 1e30 0 0\n0.5 0.5 0.5' "$TMP/cube.off" >"$TMP/stray.off"
expect 0 "2 vertex(es) used by no triangle ignored (the first at (1e+30, 0, 0))" -- info "$TMP/stray.off"
[[ "$(value bbox)" == "0 0 0 1 1 1" && "$(value vertices)" == "8" && "$(value unused_vertices)" == "2" ]] \
  || fail "stray vertices: bbox=$(value bbox) vertices=$(value vertices) unused_vertices=$(value unused_vertices)"
expect 0 "used by no triangle" -- mesh "$TMP/stray.off" --size 20% -o "$TMP/stray.mesh.off" --check
[[ "$(value g1)" == "true" ]] || fail "stray vertices: g1=$(value g1)"
# --max-seconds ends the check for self-intersections, the one step that is not linear in the
# model, with exit 1, the pairs found so far and stopped=max-seconds; every other figure is still
# printed (the limit has passed by the check's first poll: reading the fan cylinder takes longer).
# Without it, stopped=no.
write_fan_cylinder "$TMP/fan_cylinder.off" 6000
expect 1 "while checking the model for self-intersections" -- info "$TMP/fan_cylinder.off" --max-seconds 0.001
[[ "$(value stopped)" == "max-seconds" && "$(value self_intersections)" == "0" && "$(value triangles)" == "24000" ]] \
  || fail "info stopped: stopped=$(value stopped) self_intersections=$(value self_intersections) triangles=$(value triangles)"
expect 0 "" -- info "$TMP/cube.off"
[[ "$(value stopped)" == "no" ]] || fail "info: stopped=$(value stopped)"
# A FIFO nobody writes to: open() used to block for ever, past --max-seconds. Now each command
# that reads a model waits with a notice and stops at the limit (exit 1, nothing written); a
# writer that comes after the notice is read as a file is.
mkfifo "$TMP/lonely.off"
expect 1 "stopped at --max-seconds 1.5" -- info "$TMP/lonely.off" --max-seconds 1.5
grep -qF "waiting for data on $TMP/lonely.off" "$TMP/err" || fail "FIFO without writer: no notice: $(cat "$TMP/err")"
expect 1 "no data came through the pipe" -- mesh "$TMP/lonely.off" --size 20% -o "$TMP/lonely.mesh" --max-seconds 0.5
[[ ! -e "$TMP/lonely.mesh" ]] || fail "FIFO without writer: mesh wrote $TMP/lonely.mesh"
expect 1 "while reading; nothing written" -- protect "$TMP/lonely.off" --size 20% --max-seconds 0.5
(sleep 3; cat "$TMP/cube.off" >"$TMP/lonely.off") &
expect 0 "waiting for data on $TMP/lonely.off" -- info "$TMP/lonely.off" --max-seconds 30
wait
[[ "$(value triangles)" == "12" ]] || fail "FIFO with a late writer: triangles=$(value triangles)"
finish
