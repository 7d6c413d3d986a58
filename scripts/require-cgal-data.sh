#!/usr/bin/env bash
# Fetches the libcgal-demo models the real-model tests need (scripts/get-cgal-data.sh). Those
# tests fail when a model is absent (tests/support/cgal_demo_data.h), so a failed download stops
# here (exit 1) with the way to run the rest without them: DELPSC_ALLOW_MISSING_CGAL_DATA=1.
set -uo pipefail
cd "$(dirname "$0")/.."
if ! bash scripts/get-cgal-data.sh >/dev/null; then
  if [[ -z "${DELPSC_ALLOW_MISSING_CGAL_DATA:-}" ]]; then
    echo "delpsc: could not fetch the libcgal-demo models the real-model tests need;" \
      "set DELPSC_ALLOW_MISSING_CGAL_DATA=1 to run the tests without them" >&2
    exit 1
  fi
  echo "delpsc: libcgal-demo models unavailable; DELPSC_ALLOW_MISSING_CGAL_DATA is set: real-model tests skip them" >&2
fi
