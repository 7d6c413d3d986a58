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

# write_cube FILE: the unit cube [0,1]^3 as an OFF file, 12 outward-oriented triangles.
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
