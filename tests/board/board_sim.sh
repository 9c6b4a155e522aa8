#!/usr/bin/env bash
# ctest board_sim_<board>[_phong] (label board): `watkins board sim --frames 2` of the default scene
# on the Verilated board top built for SHADING (gouraud when not given; phong: --shading phong, the
# Phong top). Both rendered frames report 0 missed lines and equal the model's image, the
# run exits 0, and frame_000.png and frame_001.png are 640 x 480 PNGs. A scene that does not fit
# the top's configuration (scenes/teapot.json: more polygons than the polygon id holds) is one
# error line naming what does not fit, exit 1, and no folder of frames. On the iCEBreaker a scene
# built to miss exits 4 with its missed lines counted and its frame written.
#   board_sim.sh WATKINS SOURCE_DIR WORK_DIR BOARD [SHADING]
set -euo pipefail
watkins=$1 src=$2 work=$3 board=$4 shading=${5:-gouraud}
rm -rf "$work"
mkdir -p "$work"
name=board_sim_$board$([ "$shading" = gouraud ] || echo "_$shading")
fail() { echo "$name: $*"; cat "$work/out.txt"; exit 1; }

"$watkins" board sim --board "$board" --shading "$shading" --frames 2 --out "$work/frames" > "$work/out.txt" 2>&1 ||
  fail "exit $?"
cat "$work/out.txt"
grep -qE "^scene +.* shading $shading, " "$work/out.txt" || fail "the scene is not shaded $shading"
for f in 0 1; do
  grep -qE "^frame $f +0 missed lines, equals the model's image; " "$work/out.txt" ||
    fail "frame $f: not 0 missed lines and equal to the model"
  png="$work/frames/frame_00$f.png"
  [ -s "$png" ] || fail "no $png"
  [ "$(od -An -tu1 -N 8 "$png" | tr -s ' ')" = " 137 80 78 71 13 10 26 10" ] || fail "$png is not a PNG"
  # IHDR: the width and the height, big-endian, at bytes 16 and 20.
  [ "$(od -An -tu1 -j 16 -N 8 "$png" | tr -s ' ')" = " 0 0 2 128 0 0 1 224" ] || fail "$png is not 640 x 480"
done
grep -qE "^total +2 frames: 0 missed lines, 2 equal the model's image; " "$work/out.txt" || fail "no total line"

rc=0
"$watkins" board sim "$src/scenes/teapot.json" --board "$board" --shading "$shading" --frames 1 --out "$work/teapot" \
  > "$work/teapot.txt" 2>&1 || rc=$?
[ "$rc" -eq 1 ] || { cat "$work/teapot.txt"; fail "teapot: exit $rc, not 1"; }
[ "$(wc -l < "$work/teapot.txt")" -eq 1 ] || { cat "$work/teapot.txt"; fail "teapot: not one line"; }
grep -q "does not fit the $board board top .*polygon" "$work/teapot.txt" ||
  { cat "$work/teapot.txt"; fail "teapot: the line does not name the polygons"; }
[ ! -e "$work/teapot" ] || fail "teapot: the folder of frames was created"
# On the iCEBreaker, a scene built to miss (tests/board/miss_doubled.json): exit 4, the frame's
# missed lines counted, the frame written.
if [ "$board" = icebreaker ] && [ "$shading" = gouraud ]; then
  rc=0
  "$watkins" board sim "$src/tests/board/miss_doubled.json" --board "$board" --frames 1 --out "$work/miss" \
    > "$work/miss.txt" 2>&1 || rc=$?
  [ "$rc" -eq 4 ] || { cat "$work/miss.txt"; fail "miss_doubled: exit $rc, not 4"; }
  grep -qE "^frame 0 +[1-9][0-9]* missed lines, differs from the model's image; " "$work/miss.txt" ||
    { cat "$work/miss.txt"; fail "miss_doubled: no missed lines reported"; }
  [ -s "$work/miss/frame_000.png" ] || fail "miss_doubled: no frame_000.png"
fi
echo "$name: OK"
