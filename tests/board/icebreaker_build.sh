#!/usr/bin/env bash
# ctest icebreaker_board_build (label synth): `watkins board build --board icebreaker` of one
# triangle (tests/board/tiny.json) through the whole flow: the deadline check, the bank's flash
# image, yosys synth_ice40, nextpnr-ice40 with the board's pins, icepack. The configuration is
# tests/board/tiny.icebreaker.json: the triangle's sized one, built compact, with 8 active edges
# (at the sized 2 yosys keeps the list's 3 words in flip-flops, and the design takes 5,419 of the
# UP5K's 5,280 logic cells; at 8 they go to block RAM). A .bin that holds the iCE40's
# synchronization word and the scene bank at 128 KiB, the report's logic cells, block RAM and
# SPRAM, the one clock routed at or above its 25.125 MHz (seed 1).
#   icebreaker_build.sh WATKINS SOURCE_DIR WORK_DIR
set -euo pipefail
watkins=$1 src=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
"$watkins" board build "$src/tests/board/tiny.json" --board icebreaker --config "$src/tests/board/tiny.icebreaker.json" \
  --seed 1 --work "$work/flow" --out "$work/tiny.bin" --md "$work/tiny.md" > "$work/out.txt" ||
  { cat "$work/out.txt"; exit 1; }
[ -s "$work/tiny.bin" ] || { echo "icebreaker_board_build: no bitstream"; exit 1; }
LC_ALL=C grep -qaF $'\x7e\xaa\x99\x7e' "$work/tiny.bin" ||
  { echo "icebreaker_board_build: no iCE40 synchronization word in the .bin"; exit 1; }
# The scene after the bitstream: 16 bank words of 3 SPRAM words, 384 bytes from 131,072 on; bank
# word 0 is N, the triangle's 3 edge records.
[ "$(stat -c %s "$work/tiny.bin")" -eq $((131072 + 384)) ] ||
  { echo "icebreaker_board_build: the .bin is not 128 KiB and the bank's 384 bytes"; exit 1; }
[ "$(od -An -tu1 -j 131072 -N 1 "$work/tiny.bin" | tr -d ' ')" = 3 ] ||
  { echo "icebreaker_board_build: bank word 0 at 128 KiB is not N = 3"; exit 1; }
grep -q "| ICESTORM_SPRAM | 4 | " "$work/tiny.md" || { echo "icebreaker_board_build: the SPRAMs are not used"; exit 1; }
grep -q "| ICESTORM_LC | " "$work/tiny.md" || { echo "icebreaker_board_build: no logic cells in the report"; exit 1; }
grep -q "| ICESTORM_RAM | " "$work/tiny.md" || { echo "icebreaker_board_build: no block RAM in the report"; exit 1; }
grep -qE '^\| `clk` \| 25\.1 \| [0-9.]+ \| \+[0-9.]+ % \| yes \|$' "$work/tiny.md" ||
  { echo "icebreaker_board_build: the clock is not reported met against 25.1 MHz"; cat "$work/tiny.md"; exit 1; }
cat "$work/tiny.md"
echo "icebreaker_board_build: OK"
