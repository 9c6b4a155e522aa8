#!/usr/bin/env bash
# Sets up, builds and runs the main job on the embedded default scene: the RTL pipeline under
# Verilator and SystemC, compared pixel for pixel with the bit-exact model and with the double
# reference. Writes out/default.png, out/default_diff.png and out/default_report.txt.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="${WATKINS_BUILD:-$root/build}"
"$root/scripts/setup.sh"
mkdir -p "$root/out"
rtl=()
"$build/watkins" render --help | grep -q -- '--rtl' && rtl=(--rtl)
"$build/watkins" render "${rtl[@]}" --out "$root/out/default.png" --diff "$root/out/default_diff.png" \
  | tee "$root/out/default_report.txt"
