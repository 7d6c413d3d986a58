#!/usr/bin/env bash
# Installs the Debian packages delpsc needs that are missing; installs nothing that is present.
#   scripts/install-deps.sh            library, command, tests' oracle, benchmarks
#   scripts/install-deps.sh --cgal     also libcgal-dev, for the optional cross-checks
set -euo pipefail
# python3: the command tests validate the JSON reports with python3 -m json.tool.
packages=(cmake g++ make libeigen3-dev libnanoflann-dev doctest-dev libbenchmark-dev libgmp-dev libcli11-dev python3)
if [[ "${1:-}" == "--cgal" ]]; then packages+=(libcgal-dev); fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

echo "delpsc: installing ${missing[*]}" >&2
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
