#!/usr/bin/env bash
# docs/results/icebreaker.md: the iCEBreaker board top (the compact pipeline on the iCE40 UP5K, one
# 25.125 MHz clock, the 12-bit DVI Pmod) on the default scene at 320x240 shown doubled:
# `watkins board check --board icebreaker` (the beam schedule: budget, worst line and slack,
# missed lines) and `watkins board build --board icebreaker` (yosys, nextpnr-ice40, icepack: the
# resources and the clock's routed Fmax against 25.125 MHz) at nextpnr's default seed and at seeds
# 1 and 2; then `watkins board check` of overdraw, the one shipped scene that needs two fragment
# lanes. Each build takes 3 to 10 minutes; two run side by side.
#   scripts/lib/icebreaker_figures.sh [OUTDIR]     WATKINS_ICEBREAKER_SEEDS=0,1,2: the seeds built
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/scripts/lib/results_header.sh"
results_begin icebreaker "${1:-}"
md="$out/icebreaker.md"
IFS=',' read -r -a seeds <<<"${WATKINS_ICEBREAKER_SEEDS:-0,1,2}"
{
  results_header "${WATKINS_ICEBREAKER_SEEDS:+WATKINS_ICEBREAKER_SEEDS=$WATKINS_ICEBREAKER_SEEDS }scripts/results icebreaker"
  echo
  echo "# The iCEBreaker board top"
  echo
  echo "The compact pipeline on the iCEBreaker (iCE40 UP5K), racing the beam into a two-line buffer read by"
  echo "640x480 at 60 Hz through the 12-bit DVI Pmod, one 25.125 MHz clock for video and pipeline"
  echo "([../reference/board.md](../reference/board.md), \"iCEBreaker\"; the guide:"
  echo "[../guide/board.md](../guide/board.md)). \`watkins board check\` proves the beam deadline with the"
  echo "cycle model before the bitstream; \`watkins board build\` places and routes it (the scene bank goes"
  echo "into the SPI flash image beside the bitstream) and reports the clock's routed Fmax against its"
  echo "constraint."
  echo
  echo "## the default scene, 320x240 shown doubled"
  echo
  echo '`watkins board check --board icebreaker`:'
  echo
  echo '```'
  "$build/watkins" board check --board icebreaker
  echo '```'
} > "$tmp/head.md"

ok=0
pids=()
for s in "${seeds[@]}"; do
  "$build/watkins" board build --board icebreaker --seed "$s" --work "$tmp/s$s" --out "$tmp/s$s.bin" \
      --md "$tmp/s$s.md" > "$tmp/s$s.log" 2>&1 &
  pids+=("$!")
  # Two at a time: nextpnr-ice40 places and routes on one core.
  if [ "${#pids[@]}" -ge 2 ]; then wait "${pids[0]}" || ok=1; pids=("${pids[@]:1}"); fi
done
for p in "${pids[@]}"; do wait "$p" || ok=1; done
: > "$tmp/body.md"
for s in "${seeds[@]}"; do
  label="nextpnr's default seed"
  [ "$s" != 0 ] && label="seed $s"
  if [ -f "$tmp/s$s.md" ] && [ -f "$tmp/s$s.bin" ]; then
    {
      echo
      echo "### \`watkins board build --board icebreaker --seed $s\` ($label): $(stat -c %s "$tmp/s$s.bin") bytes"
      echo
      cat "$tmp/s$s.md"
    } >> "$tmp/body.md"
  else
    ok=1
    {
      echo
      echo "### \`watkins board build --board icebreaker --seed $s\` failed"
      echo
      echo '```'
      tail -5 "$tmp/s$s.log"
      echo '```'
    } >> "$tmp/body.md"
  fi
done
{
  echo
  echo "## overdraw: two fragment lanes"
  echo
  echo "Eight screen-wide quads, 2,548 fragments a line: one lane (a fragment a clock) misses lines, so the"
  echo "sized compact configuration takes two ([../reference/compact.md](../reference/compact.md), \"Lanes\")."
  echo
  echo '`watkins board check scenes/overdraw.json --board icebreaker`:'
  echo
  echo '```'
  "$build/watkins" board check "$root/scenes/overdraw.json" --board icebreaker || true
  echo '```'
} >> "$tmp/body.md"
cat "$tmp/head.md" "$tmp/body.md" | sed "s|$root/||g" > "$md"
echo "icebreaker: $md ($(( $(date +%s) - start )) s)"
exit $ok
