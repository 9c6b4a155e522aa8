#!/usr/bin/env bash
# Prints the error figures of the Phong blocks' models against double precision:
# the normalizer (exhaustive inverse sqrt, every exponent class, near-null and antipodal
# normals, 10^7 random inputs: max error in ulps of the Q2.14 output and ||unit| - 1|), and
# with --shader also the Phong shader (max error in 8-bit levels). Same programs as the ctests
# PhongNormalizerError / PhongShaderError (tests/rtl/*_error.cpp), fixed seeds.
# --narrow measures the narrow set (config "phong": {"formats": "narrow"}) instead.
# Usage: scripts/lib/normalizer_ulp.sh [--shader] [--narrow] [random-count]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
shader=0
if [[ "${1:-}" == "--shader" ]]; then shader=1; shift; fi
set_flag=()
if [[ "${1:-}" == "--narrow" ]]; then set_flag=(--narrow); shift; fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
g++ -std=c++17 -O2 -I"$root/model/twins" "$root/tests/rtl/normalizer_error.cpp" "$root/model/twins/normalizer.cpp" "$root/model/twins/rsqrt_unit.cpp" \
  -o "$tmp/normalizer_error"
"$tmp/normalizer_error" ${set_flag[@]+"${set_flag[@]}"} "$@"
if [[ $shader == 1 ]]; then
  g++ -std=c++17 -O2 -I"$root/model/twins" "$root/tests/rtl/shader_error.cpp" "$root/model/twins/normalizer.cpp" "$root/model/twins/rsqrt_unit.cpp" \
    "$root/model/twins/phong_shader.cpp" -o "$tmp/shader_error"
  "$tmp/shader_error" ${set_flag[@]+"${set_flag[@]}"}
fi
