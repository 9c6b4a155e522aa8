#!/usr/bin/env bash
# Where the Verilated top spends its instructions, per RTL block: callgrind runs the speed
# program (watkins_rtl_speed_cc, the plain C++ harness) for 1 and 3 frames of the default scene,
# the difference over the simulated cycles is the cost per cycle (load-independent), and the
# Verilated code's per-line counts are summed by the instance each statement names
# (scripts/lib/rtl_profile.py). Line counts need debug information in the Verilated code, so use a
# build of its own:
#   cmake -S . -B build-prof -DCMAKE_BUILD_TYPE=Release -DWATKINS_TESTS=OFF \
#     -DWATKINS_RTL_SYSTEMC=OFF -DWATKINS_RTL_CONFIGS="" -DCMAKE_CXX_FLAGS=-g
#   cmake --build build-prof -j2 --target watkins_rtl_speed_cc
#   WATKINS_BUILD=build-prof scripts/lib/rtl_profile.sh [gouraud|phong] [DEPTH] [ROWS]
# DEPTH 1: per block (u_scanline_buffer, ...); 2: per block and signal or generate scope.
# Attribution is by the first instance named in a statement's lines (continuation lines go with
# it): a guide to where the cost is, not an exact account.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build="${WATKINS_BUILD:-$root/build}"
shading="${1:-gouraud}"
depth="${2:-1}"
rows="${3:-25}"
prog="$build/testbench/watkins_rtl_speed_cc"
[ -x "$prog" ] || { echo "rtl_profile: $prog not built (see the header of $0)" >&2; exit 1; }
command -v valgrind >/dev/null || { echo "rtl_profile: valgrind not installed" >&2; exit 1; }
prefix=Vwatkins_top_fast
[ "$shading" = phong ] && prefix=Vwatkins_top_fast_phong
gen="$build/testbench/CMakeFiles/watkins_tb.dir/$prefix.dir"
[ -d "$gen" ] || { echo "rtl_profile: no Verilated code in $gen" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
refs=()
for r in 1 3; do
  valgrind --tool=callgrind --callgrind-out-file="$tmp/cg$r.out" "$prog" --repeat $r --shading "$shading" \
    >"$tmp/run$r.log" 2>&1
  refs+=("$(sed -n 's/.*I *refs: *\([0-9,]*\).*/\1/p' "$tmp/run$r.log" | tr -d ,)")
done
cycles3=$(sed -n 's/^speed .*over 3 frames (\([0-9]*\) cycles.*/\1/p' "$tmp/run3.log")
cycles=$((cycles3 * 2 / 3))  # two frames: 3-frame run minus 1-frame run
echo "machine      $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(date -u +%Y-%m-%d)"
echo "top          $shading, default scene, $cycles cycles in the 2 frames measured"
echo "per cycle    $(( (refs[1] - refs[0]) / cycles )) instructions (callgrind, 3 frames minus 1, stage checker on)"
callgrind_annotate --auto=yes --context=0 --include="$gen" "$tmp/cg3.out" >"$tmp/ann.txt" 2>/dev/null
python3 "$root/scripts/lib/rtl_profile.py" "$tmp/ann.txt" "$cycles3" "$depth" "$rows"
