#!/usr/bin/env bash
# ctest icebreaker_board_build (label synth): `watkins board build --board icebreaker` of one
# triangle (tests/board/tiny.json, built compact at its sized configuration) through the whole
# flow: the deadline check, the bank image, yosys synth_ice40, nextpnr-ice40 with the board's pins,
# icepack. A .bin that starts with the iCE40's synchronization word, the report's logic cells and
# block RAM, the one clock routed at or above its 25.125 MHz. Seed 1 (nextpnr's default seed
# routes this netlist a hair under 25.1 MHz: the compact active-edge list's key compare). About
# two minutes alone.
#   icebreaker_build.sh WATKINS SOURCE_DIR WORK_DIR
set -euo pipefail
watkins=$1 src=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
"$watkins" board build "$src/tests/board/tiny.json" --board icebreaker --seed 1 --work "$work/flow" \
  --out "$work/tiny.bin" --md "$work/tiny.md" > "$work/out.txt" || { cat "$work/out.txt"; exit 1; }
[ -s "$work/tiny.bin" ] || { echo "icebreaker_board_build: no bitstream"; exit 1; }
LC_ALL=C grep -qaF $'\x7e\xaa\x99\x7e' "$work/tiny.bin" ||
  { echo "icebreaker_board_build: no iCE40 synchronization word in the .bin"; exit 1; }
grep -q "| ICESTORM_LC | " "$work/tiny.md" || { echo "icebreaker_board_build: no logic cells in the report"; exit 1; }
grep -q "| ICESTORM_RAM | " "$work/tiny.md" || { echo "icebreaker_board_build: no block RAM in the report"; exit 1; }
grep -qE '^\| `clk` \| 25\.1 \| [0-9.]+ \| \+[0-9.]+ % \| yes \|$' "$work/tiny.md" ||
  { echo "icebreaker_board_build: the clock is not reported met against 25.1 MHz"; cat "$work/tiny.md"; exit 1; }
cat "$work/tiny.md"
echo "icebreaker_board_build: OK"
