#!/usr/bin/env bash
# delpsc info: counts and defects of a small model with a duplicate vertex and a zero-area face.
source "$(dirname "$0")/lib.sh"

# Two triangles of a square sheet (a boundary of 4 edges), vertex 4 duplicates vertex 0, and a
# zero-area triangle (repeated index).
printf 'OFF\n5 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 0\n3 0 1 2\n3 4 2 3\n3 1 1 2\n' >"$TMP/sheet.off"
expect 0 "zero-area" -- info "$TMP/sheet.off"
[[ "$(value triangles)" == "3" ]] || fail "triangles: $(value triangles)"
[[ "$(value merged_vertices)" == "1" ]] || fail "merged_vertices: $(value merged_vertices)"
[[ "$(value zero_area_triangles)" == "1" ]] || fail "zero_area_triangles: $(value zero_area_triangles)"
[[ "$(value boundary_edges)" == "4" ]] || fail "boundary_edges: $(value boundary_edges)"
[[ "$(value bbox)" == "0 0 0 1 1 0" ]] || fail "bbox: $(value bbox)"
[[ "$(value self_intersections)" == "0" ]] || fail "self_intersections: $(value self_intersections)"
# A self-intersecting model: info counts the crossing pairs and warns, and still succeeds.
write_crossing "$TMP/crossing.off"
expect 0 "cross or overlap" -- info "$TMP/crossing.off"
[[ "$(value self_intersections)" == "1" ]] || fail "crossing: self_intersections=$(value self_intersections)"

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

expect 2 "cannot open" -- info "$TMP/none.ply"
printf 'ply\nformat ascii 1.0\nelement vertex 99999999999\n' >"$TMP/absurd.ply"
expect 2 "absurd.ply" -- info "$TMP/absurd.ply"
expect 2 "" -- info "$TMP/sheet.off" --angle -5
finish
