#!/usr/bin/env bash
# delpsc triangulate: success paths and bad input, run on the built binary.
source "$(dirname "$0")/lib.sh"

expect 0 "" -- triangulate --generate uniform:2000 --check
[[ "$(value valid)" == "true" ]] || fail "uniform:2000 not valid"
[[ "$(value vertices)" == "2000" ]] || fail "uniform:2000 should have 2000 vertices, got $(value vertices)"
[[ "$(value finite_cells)" -gt 6000 ]] || fail "too few cells: $(value finite_cells)"

expect 0 "" -- triangulate --generate weighted:3000 --check --remove 300 --seed 5
[[ "$(value valid_after_remove)" == "true" ]] || fail "not valid after removals"
[[ "$(value removed)" == "300" ]] || fail "removed $(value removed) of 300"
[[ "$(value remove_refused)" == "0" ]] || fail "remove_refused=$(value remove_refused) of 300"
# Removal stops at four affinely independent vertices: the rest are refused, counted and said.
expect 0 "996 of them removed" -- triangulate --generate sphere:1000 --remove 999
[[ "$(value removed)" == "996" && "$(value remove_refused)" == "3" ]] \
  || fail "999 of 1000: removed=$(value removed) remove_refused=$(value remove_refused)"

# A text file with a duplicate point and a weight: the lighter duplicate is hidden.
printf '0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1 0.5\n0 0 0 0.25\n' >"$TMP/pts.txt"
expect 0 "" -- triangulate "$TMP/pts.txt" --check
[[ "$(value hidden)" == "1" ]] || fail "expected 1 hidden point, got $(value hidden)"

# Coplanar input never reaches dimension 3: reported, not a crash.
printf '0 0 0\n1 0 0\n0 1 0\n1 1 0\n' >"$TMP/flat.txt"
expect 0 "the points span only dimension 2" -- triangulate "$TMP/flat.txt"
[[ "$(value dimension)" == "2" ]] || fail "coplanar set: dimension $(value dimension)"
# An empty point file is an error, not a report of nothing; so is removing more vertices than
# there are (it was silently cut to what there was).
: >"$TMP/empty.txt"
expect 2 "empty.txt: no points" -- triangulate "$TMP/empty.txt"
expect 2 "--remove 1000: the triangulation has only 5 vertices" -- triangulate --generate uniform:5 --remove 1000

expect 2 "cannot open" -- triangulate "$TMP/missing.bin"
printf 'garbage here\n' >"$TMP/bad.txt"
expect 2 "is not a number" -- triangulate "$TMP/bad.txt"
head -c 40 /dev/urandom >"$TMP/bad.bin"
expect 2 "not a multiple of 32" -- triangulate "$TMP/bad.bin"
# /dev/zero behind a .bin name read as 0 points (exit 0), behind a text name until memory ran out.
ln -s /dev/zero "$TMP/zero.bin"
expect 2 "zero.bin: is a device or socket, not a point set file" -- triangulate "$TMP/zero.bin"
ln -s /dev/zero "$TMP/zero.txt"
expect 2 "zero.txt: is a device or socket" -- triangulate "$TMP/zero.txt"
expect 2 "unknown kind" -- triangulate --generate cube:10
# More points than memory holds (320 bytes each, 80% of memory): refused before any is made.
# Below 70 GB of memory 2e8 points are too many; a larger machine would try them, so skip there.
if [ "$(awk '/MemTotal/ {print $2}' /proc/meminfo)" -lt 70000000 ]; then
  expect 2 "more than the memory this process may use" -- triangulate --generate uniform:200000000
fi
expect 2 "" -- triangulate --generate uniform:10 --remove -3
expect 2 "exactly one" -- triangulate "$TMP/pts.txt" --generate uniform:10
expect 2 "" -- triangulate --no-such-option
finish
