#!/usr/bin/env bash
# RTL figures: fragments per cycle of the Verilated pipeline (default scene: bound by the one-
# pixel-per-clock output in full-frame mode, by the fragment path in sparse mode (--sparse: covered
# pixels only); overdraw scene: bound by the fragment rate), and simulated cycles per
# second with the SystemC bench against a plain C++ harness on the same RTL.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build="${WATKINS_BUILD:-$root/build}"
[ -x "$build/testbench/watkins_rtl_speed_sc" ] || { echo "rtl: not built (needs Verilator and SystemC)"; exit 0; }
for run in ":" ":--sparse" "$root/scenes/overdraw.json:" "$root/scenes/overdraw.json:--sparse"; do
  scene=${run%%:*}
  mode=${run#*:}
  out=$("$build/watkins" render $scene --rtl $mode --out "$(mktemp -u).png")
  name=$(basename "${scene:-default}" .json)${mode:+ sparse}
  frag=$(echo "$out" | sed -n 's/^rtl pixels.*fragments \([0-9]*\) (model), \([0-9.]*\) fragments\/cycle, \([0-9.]*\) pixels\/cycle/\1 fragments, \2 fragments\/cycle, \3 pixels\/cycle/p')
  cyc=$(echo "$out" | sed -n 's/^rtl cycles *\([0-9]*\).*/\1/p')
  mism=$(echo "$out" | sed -n "s/^rtl vs model *\([0-9]*\) mismatching.*/\1/p")
  printf "rtl %-16s %s cycles, %s; %s mismatches\n" "$name" "$cyc" "$frag" "$mism"
done
for h in sc cc; do
  exe="$build/testbench/watkins_rtl_speed_$h"
  [ -x "$exe" ] || continue
  speed=$("$exe" --repeat 3 | sed -n 's/^speed *\([0-9]*\) cycles\/s.*/\1/p')
  desc=$([ "$h" = sc ] && echo "SystemC bench (one SC_THREAD clocks the model)" || echo "plain C++ harness (eval loop)")
  printf "verilator %-48s %s cycles/s\n" "$desc" "$speed"
done
