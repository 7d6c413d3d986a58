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

finish() {
  echo "$passes passed, $failures failed"
  [[ $failures -eq 0 ]]
}
