#!/usr/bin/env bash
# RTL figures: cycles per frame and fragments per cycle of the Verilated pipeline, Gouraud and
# Phong shading (watkins_top with Phong = 0 and 1), in full-frame output (bound by one pixel per
# clock) and sparse output (--sparse: covered pixels only, bound by the fragment path); the
# overdraw scene is bound by the fragment rate. Then simulated cycles per second of both tops on
# the plain C++ harness (the speed build: no assertions, no tracing) and on both builds of the
# SystemC bench: the one the tests run (assertions and tracing compiled in) and its speed build
# (watkins_rtl_speed_sc_fast: --sc tops without assertions or tracing; not in the default build,
# so this script builds that target first, -j${WATKINS_JOBS:-2}).
set -euo pipefail
root=$(cd "$(dirname "$0")/../../.." && pwd)
build="${WATKINS_BUILD:-$root/build}"
[ -x "$build/testbench/watkins_rtl_speed_sc" ] && [ -x "$build/testbench/watkins_rtl_speed_cc" ] ||
  { echo "rtl: not built (needs Verilator, SystemC, WATKINS_RTL_SPEED and WATKINS_RTL_SYSTEMC)"; exit 0; }
harnesses=(cc sc)
if cmake --build "$build" -j"${WATKINS_JOBS:-2}" --target watkins_rtl_speed_sc_fast >"$build/sc_fast_build.log" 2>&1; then
  harnesses+=(sc_fast)
else
  echo "rtl: the SystemC bench's speed build did not build (log: $build/sc_fast_build.log); its figures are left out"
fi
scenes=("" "$root/scenes/sphere.json" "$root/scenes/cone.json" "$root/scenes/overdraw.json")
printf "%-26s %9s %9s %8s %11s %10s\n" "rtl frame" "cycles" "fragments" "frag/cyc" "pixels/cyc" "mismatches"
for scene in "${scenes[@]}"; do
  for shading in gouraud phong; do
    for mode in "" "--sparse"; do
      out=$("$build/watkins" render $scene --shading $shading --rtl $mode --out "$(mktemp -u).png")
      name="$(basename "${scene:-default}" .json) $shading${mode:+ sparse}"
      read -r frag fpc ppc < <(echo "$out" | sed -n 's/^rtl pixels.*fragments \([0-9]*\) (model), \([0-9.]*\) fragments\/cycle, \([0-9.]*\) pixels\/cycle/\1 \2 \3/p')
      cyc=$(echo "$out" | sed -n 's/^rtl cycles *\([0-9]*\).*/\1/p')
      mism=$(echo "$out" | sed -n "s/^rtl vs model *\([0-9]*\) mismatching.*/\1/p")
      printf "%-26s %9s %9s %8s %11s %10s\n" "$name" "$cyc" "$frag" "$fpc" "$ppc" "$mism"
    done
  done
done
speed() {  # $1: harness (sc, sc_fast, cc), $2: shading
  "$build/testbench/watkins_rtl_speed_$1" --repeat 3 --shading "$2" | sed -n 's/^speed *\([0-9]*\) cycles\/s.*/\1/p'
}
label() {  # $1: harness, $2: shading
  case $1 in
    cc) echo "plain C++ harness, $2 top (speed build, eval loop)" ;;
    sc) echo "SystemC bench, $2 top (assertions; one SC_THREAD)" ;;
    sc_fast) echo "SystemC bench, $2 top (speed build; one SC_THREAD)" ;;
  esac
}
# Every bench, both tops, in one run (the machine is shared: compare figures of the same run).
for shading in gouraud phong; do
  for h in "${harnesses[@]}"; do
    printf "verilator %-60s %s cycles/s\n" "$(label $h $shading)" "$(speed $h $shading)"
  done
done
# Instructions per simulated cycle (callgrind: repeatable on a shared machine): the difference
# between a 3-frame and a 1-frame run over the difference in cycles, so the warm-up frame and the
# set-up cancel; with the stage checker off, the Verilated model alone.
if command -v valgrind >/dev/null; then
  per_cycle() {  # $1: harness (sc, cc); then extra options
    local h=$1 ir=() cyc=()
    shift
    for r in 1 3; do
      out=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null \
        "$build/testbench/watkins_rtl_speed_$h" --repeat $r "$@" 2>&1)
      ir+=("$(echo "$out" | sed -n 's/.*I *refs: *\([0-9,]*\)/\1/p' | tr -d ,)")
      cyc+=("$(echo "$out" | sed -n 's/^speed .*over [0-9]* frames (\([0-9]*\) cycles.*/\1/p')")
    done
    echo $(( (ir[1] - ir[0]) / (cyc[1] - cyc[0]) ))
  }
  for shading in gouraud phong; do
    printf "verilator %-60s %s instructions/cycle\n" "plain C++ harness, ${shading} top, no stage checker" \
      "$(per_cycle cc --shading $shading --no-stage-check)"
    printf "verilator %-60s %s instructions/cycle\n" "plain C++ harness, ${shading} top, stage checker on" \
      "$(per_cycle cc --shading $shading)"
  done
  for shading in gouraud phong; do
    printf "verilator %-60s %s instructions/cycle\n" "SystemC bench, ${shading} top (assertions), stage checker on" \
      "$(per_cycle sc --shading $shading)"
    if [[ " ${harnesses[*]} " == *" sc_fast "* ]]; then
      printf "verilator %-60s %s instructions/cycle\n" "SystemC bench, ${shading} top (speed build), stage checker on" \
        "$(per_cycle sc_fast --shading $shading)"
    fi
  done
fi
