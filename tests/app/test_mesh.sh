#!/usr/bin/env bash
# delpsc mesh: a unit cube written by hand, meshed at sizes given as lengths and percentages; the
# report, G1 (--check), the written mesh (OFF counts, a closed genus-0 surface, Medit labels), --balls,
# --max-vertices (exit 1, mesh still written, failing vertices listed), and bad input (exit 2).
source "$(dirname "$0")/lib.sh"

write_cube "$TMP/cube.off"

expect 0 "" -- mesh "$TMP/cube.off" --size 10% -o "$TMP/cube.off.out.off" --balls "$TMP/balls.txt" --check
[[ "$(value g1)" == "true" ]] || fail "g1=$(value g1)"
[[ "$(value disk_condition)" == "ok" ]] || fail "disk_condition=$(value disk_condition)"
[[ "$(value patches)" == "6" && "$(value curves)" == "12" && "$(value corners)" == "8" ]] \
  || fail "patches/curves/corners: $(value patches)/$(value curves)/$(value corners)"
v=$(value vertices); t=$(value triangles)
[[ "$v" -gt 8 ]] || fail "vertices=$v"
# A closed surface of genus 0: V - E + F = 2 with E = 3F/2, i.e. F = 2V - 4.
[[ "$t" -eq $((2 * v - 4)) ]] || fail "triangles=$t for vertices=$v: not a sphere"
[[ "$(value balls)" -ge 8 ]] || fail "balls=$(value balls)"
awk -v a="$(value min_angle)" 'BEGIN { exit !(a > 0 && a <= 60) }' || fail "min_angle=$(value min_angle)"
for key in ball_refinements seconds_protect seconds_refine seconds; do
  [[ -n "$(value $key)" ]] || fail "no $key in the report"
done
lambda=$(value lambda)
awk -v l="$lambda" 'BEGIN { exit !(l > 0.1731 && l < 0.1733) }' || fail "10% of sqrt(3): lambda=$lambda"
read -r nv nt _ < <(sed -n 2p "$TMP/cube.off.out.off")
[[ "$nv" == "$v" && "$nt" == "$t" ]] || fail "OFF file holds $nv vertices, $nt triangles; report $v, $t"
[[ $(grep -c '^corner ' "$TMP/balls.txt") -eq 8 ]] || fail "--balls: not 8 corner lines"

# The same size as a length; Medit output with labels: 8 corners, 6 patch references.
expect 0 "" -- mesh "$TMP/cube.off" --size "$lambda" -o "$TMP/cube.mesh"
[[ "$(value vertices)" == "$v" ]] || fail "--size $lambda gave $(value vertices) vertices, 10% gave $v"
awk '/^Corners/ { getline; c = $1 } /^Triangles/ { getline; n = $1; for (i = 0; i < n; i++) { getline; ref[$4] = 1 } }
     END { k = 0; for (r in ref) k++; exit !(c == 8 && k == 6) }' "$TMP/cube.mesh" \
  || fail "cube.mesh: not 8 corners and 6 patch references"

# A finer mesh has more vertices.
expect 0 "" -- mesh "$TMP/cube.off" --size 5% -o "$TMP/fine.vtu" --check
[[ "$(value g1)" == "true" ]] || fail "5%: g1=$(value g1)"
[[ "$(value vertices)" -gt "$v" ]] || fail "5% gave $(value vertices) vertices, 10% gave $v"
[[ "$(value disk_condition)" == "ok" ]] || fail "5%: disk_condition=$(value disk_condition)"

# The vertex cap: exit 1, a message, the failing vertices listed, the mesh reached written.
expect 1 "max-vertices" -- mesh "$TMP/cube.off" --size 5% --max-vertices 40 -o "$TMP/capped.off"
[[ -s "$TMP/capped.off" ]] || fail "--max-vertices: no mesh written"
grep -q "disk condition D[1-4] fails at vertex" "$TMP/err" || fail "--max-vertices: failing vertices not listed"
[[ "$(value disk_condition)" =~ ^[0-9]+$ ]] || fail "--max-vertices: disk_condition=$(value disk_condition)"

# CGAL-style criteria: facet_distance and facet_angle refine further than the size alone.
expect 0 "" -- mesh "$TMP/cube.off" --size 10% --facet-distance 0.1% --facet-angle 30 -o "$TMP/criteria.off" -v
[[ "$(value vertices)" -ge "$v" ]] || fail "criteria gave $(value vertices) vertices, size alone $v"
[[ "$(value disk_condition)" == "ok" ]] || fail "criteria: disk_condition=$(value disk_condition)"
expect 2 "facet-angle" -- mesh "$TMP/cube.off" --facet-angle 31 -o "$TMP/x.off"
expect 2 "--facet-distance" -- mesh "$TMP/cube.off" --facet-distance -1 -o "$TMP/x.off"

# Bad input.
expect 2 "cannot open" -- mesh "$TMP/none.off" -o "$TMP/x.off"
printf 'OFF\n3 1 0\n0 0 zero\n' >"$TMP/garbage.off"
expect 2 "garbage.off" -- mesh "$TMP/garbage.off" -o "$TMP/x.off"
expect 2 "--size 0" -- mesh "$TMP/cube.off" --size 0 -o "$TMP/x.off"
expect 2 "--size -1%" -- mesh "$TMP/cube.off" --size -1% -o "$TMP/x.off"
expect 2 "unknown output format" -- mesh "$TMP/cube.off" -o "$TMP/x.xyz"
expect 2 "" -- mesh "$TMP/cube.off"
finish
