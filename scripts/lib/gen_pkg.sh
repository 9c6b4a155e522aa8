#!/usr/bin/env bash
# Regenerates rtl/watkins_pkg.sv from model/twins/formats.hpp (the one source of the formats).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
g++ -std=c++17 -I"$root/model/twins" -I"$root/model/prepare" -I"$root/model/scene" "$root/sim/gen_pkg.cpp" "$root/model/twins/config.cpp" "$root/model/prepare/config_file.cpp" "$root/model/scene/strict_json.cpp" -o "$tmp/gen_pkg"
"$tmp/gen_pkg" > "$root/rtl/watkins_pkg.sv"
echo "wrote rtl/watkins_pkg.sv"
