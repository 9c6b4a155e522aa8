#!/usr/bin/env bash
# Sets up, builds and runs the main job on the embedded default scene: the RTL pipeline under
# Verilator (the plain C++ harness), compared pixel for pixel with the bit-exact model and with the double
# reference, with Gouraud shading and then Phong shading. Writes out/default.png,
# out/default_diff.png, out/default_phong.png, out/default_phong_truth.png (the exact surfaces)
# and out/default_report.txt (both reports).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="${WATKINS_BUILD:-$root/build}"
"$root/scripts/setup.sh" --main
mkdir -p "$root/out"
rtl=()
"$build/watkins" render --help | grep -q -- '--rtl' && rtl=(--rtl)
{
  "$build/watkins" render "${rtl[@]}" --out "$root/out/default.png" --diff "$root/out/default_diff.png"
  echo
  "$build/watkins" render "${rtl[@]}" --shading phong --out "$root/out/default_phong.png" \
    --truth "$root/out/default_phong_truth.png"
} | tee "$root/out/default_report.txt"
