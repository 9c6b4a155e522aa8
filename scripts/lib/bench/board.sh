#!/usr/bin/env bash
# The virtual board (`watkins board sim`): the Verilated board tops drawing the default scene,
# frames per second (wall: the best of five rendered frames, each frame's simulation and its PNG)
# and simulated clocks per second, for the ULX3S top (pipeline clocks at 25/8 of the pixel clock)
# and the iCEBreaker's compact top (one clock); then instructions per simulated clock (callgrind:
# a two-frame run less a one-frame run over one video frame's clocks, so the set-up, the model's
# image and the warm-up frame cancel; the bench loop and a frame's PNG are counted with the top).
set -euo pipefail
root=$(cd "$(dirname "$0")/../../.." && pwd)
build="${WATKINS_BUILD:-$root/build}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if ! "$build/watkins" board sim --frames 1 --out "$work/probe" >/dev/null 2>&1; then
  echo "virtual board: not built (the board tops need WATKINS_RTL and WATKINS_TESTS)"
  exit 0
fi
for board in ulx3s icebreaker; do
  unit="clocks"
  [ "$board" = ulx3s ] && unit="pipeline clocks"
  out=$("$build/watkins" board sim --board $board --frames 5 --out "$work/$board")
  read -r fps rate < <(echo "$out" | sed -n "s/^frame .* s: \([0-9.]*\) frames\/s, \([0-9]*\) $unit\/s;.*/\1 \2/p" |
    sort -g -r | head -1)
  printf "virtual board %-10s %s frames/s, %s %s/s (watkins board sim, default scene, best of 5 frames)\n" \
    "$board" "$fps" "$rate" "$unit"
done
if command -v valgrind >/dev/null; then
  for board in ulx3s icebreaker; do
    ir=()
    for n in 1 2; do
      out=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null \
        "$build/watkins" board sim --board $board --frames $n --out "$work/cg_${board}_$n" 2>&1)
      ir+=("$(echo "$out" | sed -n 's/.*I *refs: *\([0-9,]*\)/\1/p' | tr -d ,)")
    done
    # One video frame: 420,000 pixel clocks; on the ULX3S 1,312,500 pipeline clocks.
    if [ "$board" = ulx3s ]; then clocks=1312500 unit="pipeline clock"; else clocks=420000 unit="clock"; fi
    printf "virtual board %-10s %s instructions per %s (callgrind, one video frame)\n" \
      "$board" "$(( (ir[1] - ir[0]) / clocks ))" "$unit"
  done
fi
