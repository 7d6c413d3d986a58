# Helpers for the command-line tests: each test script gets the delpsc binary as $1.
set -u
DELPSC="$1"
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
failures=0
passes=0

fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }
pass() { passes=$((passes + 1)); }

# expect CODE "message fragment" -- args...: runs delpsc, checks exit code and stderr fragment.
expect() {
  local code="$1" fragment="$2"
  shift 3
  "$DELPSC" "$@" >"$TMP/out" 2>"$TMP/err"
  local got=$?
  if [[ $got -ne $code ]]; then
    fail "delpsc $* exited $got, expected $code; stderr: $(head -c 400 "$TMP/err")"
  elif [[ -n "$fragment" ]] && ! grep -qF -- "$fragment" "$TMP/err" "$TMP/out"; then
    fail "delpsc $*: output lacks '$fragment'; stderr: $(head -c 400 "$TMP/err")"
  else
    pass
  fi
}

# value KEY: the value of KEY= in the last command's stdout.
value() { sed -n "s/^$1=//p" "$TMP/out" | head -n 1; }

# write_crossing FILE: two triangles that cross each other (a self-intersecting model); the
# commands that mesh must refuse it (exit 2) instead of refining for ever along the crossing.
write_crossing() {
  printf 'OFF\n6 2 0\n0 0 0\n1 0 0\n0 1 0\n0.2 0.2 -0.5\n0.3 0.3 0.5\n0.9 0.1 0.5\n3 0 1 2\n3 3 4 5\n' >"$1"
}

# write_fan_cylinder FILE N: a closed cylinder of N rim points whose caps are fans of N triangles
# around their centres: every two of a cap's triangles share the centre and their boxes overlap
# (N²/2 pairs each, which the check for self-intersections settles at once per flat fan, and
# tested one by one before), a model of 4N triangles that takes a while to read.
write_fan_cylinder() {
  python3 - "$1" "$2" <<'FAN'
import math, sys
n = int(sys.argv[2])
v = [(math.cos(2 * math.pi * i / n), math.sin(2 * math.pi * i / n), z) for z in (0.0, 1.0) for i in range(n)]
v += [(0.0, 0.0, 0.0), (0.0, 0.0, 1.0)]
f = []
for i in range(n):
    j = (i + 1) % n
    f += [(i, j, n + j), (i, n + j, n + i), (2 * n, j, i), (2 * n + 1, n + i, n + j)]
with open(sys.argv[1], "w") as out:
    out.write(f"OFF\n{len(v)} {len(f)} 0\n" + "".join(f"{x!r} {y!r} {z!r}\n" for x, y, z in v)
              + "".join(f"3 {a} {b} {c}\n" for a, b, c in f))
FAN
}

# write_far_cube FILE: the unit cube moved by (1e9, 2e9, -3e9), exactly (integers below 2^53): a
# model far from the origin, which the commands mesh next to it and write back in its frame.
write_far_cube() {
  write_cube "$1.near"
  awk 'NR > 2 && NR <= 10 { printf "%.0f %.0f %.0f\n", $1 + 1000000000, $2 + 2000000000, $3 - 3000000000; next } { print }' \
    "$1.near" >"$1"
}

# in_far_cube FILE...: the coordinates in FILE (its numbers above 1e8 in magnitude, taken three at
# a time line by line: radii, ids and labels are smaller) lie within 0.01 of the far cube
# (write_far_cube), and there are at least 8 points.
in_far_cube() {
  python3 - "$@" <<'CHECK'
import re, sys
points = []
for path in sys.argv[1:]:
    for line in open(path):
        big = [float(x) for x in re.findall(r"-?[0-9][0-9.e+-]*", line) if abs(float(x)) > 1e8]
        if len(big) % 3:
            sys.exit("%s: a line with %d coordinates: %s" % (path, len(big), line[:80]))
        points += [big[i:i + 3] for i in range(0, len(big), 3)]
far = [(1e9, 1e9 + 1), (2e9, 2e9 + 1), (-3e9, -3e9 + 1)]
ok = len(points) >= 8 and all(lo - 0.01 <= c <= hi + 0.01 for p in points for c, (lo, hi) in zip(p, far))
sys.exit(not ok)
CHECK
}

# write_cube FILE: the unit cube [0,1]^3 as an OFF file, 12 outward-oriented triangles.
# write_thin_torus FILE: a torus of radii 1 and 0.02 (48 x 8 quads split in two), thinner than a
# size of 10% of its diagonal (0.28): meshed there it loses its genus.
write_thin_torus() {
  awk 'BEGIN { R = 1; r = 0.02; n = 48; m = 8; pi = atan2(0, -1)
    print "OFF"; print n * m, 2 * n * m, 0
    for (i = 0; i < n; i++) for (j = 0; j < m; j++) {
      u = 2 * pi * i / n; v = 2 * pi * j / m
      printf "%.17g %.17g %.17g\n", (R + r * cos(v)) * cos(u), (R + r * cos(v)) * sin(u), r * sin(v) }
    for (i = 0; i < n; i++) for (j = 0; j < m; j++) {
      a = i * m + j; b = ((i + 1) % n) * m + j; c = ((i + 1) % n) * m + (j + 1) % m; d = i * m + (j + 1) % m
      print 3, a, b, c; print 3, a, c, d } }' >"$1"
}

# A flat 3x3 grid sheet (two triangles a square) whose two opposite triangles at the vertex
# (1, 1) are tents: each replaced by three faces rising at 70 degrees to an apex over its
# incentre. At --angle 60 every tent face is a patch of its own and the flat patch reaches round
# both tents to touch itself at (1, 1) (a pinch); at --angle 75 the tents join the flat patch.
write_tented_grid() {
  python3 - "$1" <<'PY'
import math, sys
V = [(i, j, 0.0) for j in range(4) for i in range(4)]
T = []
for j in range(3):
    for i in range(3):
        a = j * 4 + i
        for t, tent in (((a, a + 1, a + 5), (i, j) == (0, 0)), ((a, a + 5, a + 4), (i, j) == (1, 1))):
            if not tent:
                T.append(t)
                continue
            P = [V[k] for k in t]
            L = [math.dist(P[(k + 1) % 3], P[(k + 2) % 3]) for k in range(3)]
            centre = [sum(L[k] * P[k][x] for k in range(3)) / sum(L) for x in range(2)]
            inradius = 1 / sum(L)  # twice the area (1/2) over the perimeter
            V.append((centre[0], centre[1], inradius * math.tan(math.radians(70))))
            T += [(t[0], t[1], len(V) - 1), (t[1], t[2], len(V) - 1), (t[2], t[0], len(V) - 1)]
with open(sys.argv[1], "w") as f:
    f.write(f"OFF\n{len(V)} {len(T)} 0\n" + "".join("%.17g %.17g %.17g\n" % v for v in V))
    f.write("".join("3 %d %d %d\n" % t for t in T))
PY
}

# A flat sheet with two fans of triangles at the origin and two holes between them: fan A of two
# triangles from 0 to 120 degrees, fan B of one from 180 degrees to 180 + $2 (a needle below 10),
# the holes between; a ring round them (radius 1 to 2.5, zipped by angle) makes it one patch,
# pinched at the origin - a corner where the holes' two loops meet.
write_pinch_fans() {
  python3 - "$1" "$2" <<'PY'
import math, sys
w = float(sys.argv[2])
inner = [0, 60, 120, 180, 180 + w, 270]
outer = list(range(0, 360, 30))
V = [(0.0, 0.0, 0.0)]
def add(r, a):
    V.append((r * math.cos(math.radians(a)), r * math.sin(math.radians(a)), 0.0))
    return len(V) - 1
I = [add(1.0, a) for a in inner]
O = [add(2.5, a) for a in outer]
T = [(0, I[0], I[1]), (0, I[1], I[2]), (0, I[3], I[4])]  # two fans at vertex 0; holes between
i = j = 0
n, m = len(I), len(O)
while i < n or j < m:
    ai = inner[i + 1] if i + 1 < n else 360
    aj = outer[j + 1] if j + 1 < m else 360
    if j < m and (aj < ai or i == n):
        T.append((I[i % n], O[j % m], O[(j + 1) % m])); j += 1
    else:
        T.append((I[i % n], O[j % m], I[(i + 1) % n])); i += 1
with open(sys.argv[1], "w") as f:
    f.write(f"OFF\n{len(V)} {len(T)} 0\n" + "".join("%.17g %.17g %.17g\n" % v for v in V))
    f.write("".join("3 %d %d %d\n" % t for t in T))
PY
}

# write_pinched_torus FILE: a torus of six sides and 16 segments whose tube shrinks to a point
# at (1, 0, 0) (radius 0.5 |sin(u/2)|): one patch, two cones meeting at their tips - closed fans,
# a pinch mesh refuses at --angle 60; at 45 the sides' edges are curves and each fan a wedge.
write_pinched_torus() {
  python3 - "$1" <<'PY'
import math, sys
nu, nv, R, r0 = 16, 6, 1.0, 0.5
V = [(R, 0.0, 0.0)]
rings = []
for i in range(1, nu):
    u = 2 * math.pi * i / nu
    r = r0 * abs(math.sin(u / 2))
    rings.append([])
    for j in range(nv):
        v = 2 * math.pi * j / nv
        V.append(((R + r * math.cos(v)) * math.cos(u), (R + r * math.cos(v)) * math.sin(u), r * math.sin(v)))
        rings[-1].append(len(V) - 1)
T = []
for j in range(nv):
    k = (j + 1) % nv
    T += [(0, rings[0][k], rings[0][j]), (0, rings[-1][j], rings[-1][k])]
for a, b in zip(rings, rings[1:]):
    for j in range(nv):
        k = (j + 1) % nv
        T += [(a[j], a[k], b[k]), (a[j], b[k], b[j])]
with open(sys.argv[1], "w") as f:
    f.write(f"OFF\n{len(V)} {len(T)} 0\n" + "".join("%.17g %.17g %.17g\n" % v for v in V))
    f.write("".join("3 %d %d %d\n" % t for t in T))
PY
}

write_cube() {
  cat >"$1" <<'MODEL'
OFF
8 12 0
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
3 0 2 1
3 0 3 2
3 4 5 6
3 4 6 7
3 0 1 5
3 0 5 4
3 1 2 6
3 1 6 5
3 2 3 7
3 2 7 6
3 3 0 4
3 3 4 7
MODEL
}

finish() {
  echo "$passes passed, $failures failed"
  [[ $failures -eq 0 ]]
}
