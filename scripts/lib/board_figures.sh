#!/usr/bin/env bash
# docs/results/board.md: the ULX3S board top from two scenes -- the default scene at 320x240 shown
# doubled and scenes/board_native.json at 640x480 native. For each, `watkins board check` (the
# beam schedule: budget, worst line and slack, missed lines) and `watkins board build` (yosys,
# nextpnr-ecp5, ecppack: resources and every clock's routed Fmax against its constraint), and the
# board bench's captured frame of the default scene (images/board_default.png); and the build of
# one triangle (tests/board/tiny.json), the smallest bitstream, with its time. Place and route
# takes 10 to 30 minutes a scene; the scenes' builds run side by side.
#   scripts/lib/board_figures.sh [OUTDIR]     WATKINS_BOARD_SCENES=default,board_native,tiny: a subset
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/scripts/lib/results_header.sh"
results_begin board "${1:-}"
md="$out/board.md"

scenes=("default|the default scene, 320x240 shown doubled|"
        "board_native|scenes/board_native.json, 640x480 native|$root/scenes/board_native.json"
        "tiny|tests/board/tiny.json, one triangle at 320x240 doubled: the smallest build|$root/tests/board/tiny.json")
{
  results_header "${WATKINS_BOARD_SCENES:+WATKINS_BOARD_SCENES=$WATKINS_BOARD_SCENES }scripts/results board"
  echo
  echo "# The ULX3S board top"
  echo
  echo "The pipeline on the ULX3S (ECP5 LFE5U-85F), racing the beam into a two-line buffer read by"
  echo "640x480 at 60 Hz DVI ([../reference/board.md](../reference/board.md); the guide:"
  echo "[../guide/board.md](../guide/board.md)). Per scene: \`watkins board check\`, the beam deadline proven"
  echo "by the cycle model before the bitstream; then \`watkins board build\`, the bitstream with the"
  echo "resources nextpnr placed and every clock's routed Fmax against the constraint it derives from"
  echo "the 25 MHz oscillator through the PLL."
} > "$tmp/head.md"

# The scenes' builds run side by side (nextpnr-ecp5 places and routes on one core), each into a
# body part of its own, joined in the scenes' order once all have ended.
ok=0
names=()
pids=()
for s in "${scenes[@]}"; do
  IFS='|' read -r name title file <<<"$s"
  # WATKINS_BOARD_SCENES=default,tiny: only the scenes named (each build takes 10 to 30 minutes).
  [ -z "${WATKINS_BOARD_SCENES:-}" ] || [[ ",$WATKINS_BOARD_SCENES," == *",$name,"* ]] || continue
  args=()
  [ -n "$file" ] && args=("$file")
  {
    echo
    echo "## $title"
    echo
    echo "\`watkins board check ${file:+${file#"$root"/}}\`:"
    echo
    echo '```'
    "$build/watkins" board check "${args[@]}"
    echo '```'
    echo
  } > "$tmp/$name.check.md"
  "$build/watkins" board build "${args[@]}" --work "$tmp/$name" --out "$tmp/$name.bit" --md "$tmp/$name.md" \
      > "$tmp/$name.log" 2>&1 &
  names+=("$name|$file")
  pids+=("$!")
done
: > "$tmp/body.md"
for i in "${!names[@]}"; do
  IFS='|' read -r name file <<<"${names[$i]}"
  cat "$tmp/$name.check.md" >> "$tmp/body.md"
  if wait "${pids[$i]}"; then
    {
      echo "\`watkins board build ${file:+${file#"$root"/}}\`: bitstream $(stat -c %s "$tmp/$name.bit") bytes."
      echo
      cat "$tmp/$name.md"
    } >> "$tmp/body.md"
  else
    ok=1
    {
      echo "\`watkins board build ${file:+${file#"$root"/}}\` failed:"
      echo
      echo '```'
      tail -5 "$tmp/$name.log"
      echo '```'
    } >> "$tmp/body.md"
  fi
done

# The board bench's frame of the default scene: the encoders' inputs, the model's image doubled.
bench="$build/testbench/board/watkins_board_tests"
if [ -x "$bench" ]; then
  WATKINS_BOARD_PNG="$out/images/board_default.png" "$bench" --gtest_filter=Board.DefaultSceneFrameByFrame > "$tmp/bench.log"
  {
    echo
    echo "## The simulated frame"
    echo
    echo "The Verilated board top (\`ctest -L board\`) run for two frames after the first request: the"
    echo "encoders' inputs, captured, equal the model's image of the default scene doubled, bit for bit, on"
    echo "both frames, with exact 800x525 timing and 0 missed lines."
    echo
    echo "![the captured frame](images/board_default.png)"
    echo
    echo "\`$(grep -m1 'board bench:' "$tmp/bench.log" | sed 's/^board bench: //')\`"
  } >> "$tmp/body.md"
fi
# Paths as the source tree names them, not where this checkout lies.
cat "$tmp/head.md" "$tmp/body.md" | sed "s|$root/||g" > "$md"
echo "board: $md ($(( $(date +%s) - start )) s)"
exit $ok
