#!/usr/bin/env bash
# ctest icebreaker_board_build (label synth): `watkins board build --board icebreaker` of the
# default scene through the whole flow, as a user runs it: the sized configuration built compact,
# the deadline check, the bank's flash image, yosys synth_ice40, nextpnr-ice40 with the board's
# pins at its default seed, icepack (about 90 s on an idle machine). A .bin that holds the iCE40's
# synchronization word and the scene bank at 128 KiB (512 words of 24 bytes; word 0 is N, the
# scene's 278 edge records), the report's logic cells, block RAM and the four SPRAMs, and the one
# clock routed at or above its 25.125 MHz.
#   icebreaker_build.sh WATKINS SOURCE_DIR WORK_DIR
set -euo pipefail
watkins=$1 work=$3
rm -rf "$work"
mkdir -p "$work"
"$watkins" board build --board icebreaker --work "$work/flow" --out "$work/default.bin" --md "$work/default.md" \
  > "$work/out.txt" || { cat "$work/out.txt"; exit 1; }
[ -s "$work/default.bin" ] || { echo "icebreaker_board_build: no bitstream"; exit 1; }
LC_ALL=C grep -qaF $'\x7e\xaa\x99\x7e' "$work/default.bin" ||
  { echo "icebreaker_board_build: no iCE40 synchronization word in the .bin"; exit 1; }
[ "$(stat -c %s "$work/default.bin")" -eq $((131072 + 512 * 24)) ] ||
  { echo "icebreaker_board_build: the .bin is not 128 KiB and the bank's 12,288 bytes"; exit 1; }
[ "$(od -An -tu2 -j 131072 -N 2 "$work/default.bin" | tr -d ' ')" = 278 ] ||
  { echo "icebreaker_board_build: bank word 0 at 128 KiB is not N = 278"; exit 1; }
grep -q "missed        0 lines" "$work/out.txt" || { echo "icebreaker_board_build: a line misses"; cat "$work/out.txt"; exit 1; }
grep -q "| ICESTORM_SPRAM | 4 | " "$work/default.md" || { echo "icebreaker_board_build: the SPRAMs are not used"; exit 1; }
grep -q "| ICESTORM_LC | " "$work/default.md" || { echo "icebreaker_board_build: no logic cells in the report"; exit 1; }
grep -q "| ICESTORM_RAM | " "$work/default.md" || { echo "icebreaker_board_build: no block RAM in the report"; exit 1; }
grep -qE '^\| `clk` \| 25\.1 \| [0-9.]+ \| \+[0-9.]+ % \| yes \|$' "$work/default.md" ||
  { echo "icebreaker_board_build: the clock is not reported met against 25.1 MHz"; cat "$work/default.md"; exit 1; }
cat "$work/default.md"
echo "icebreaker_board_build: OK"
