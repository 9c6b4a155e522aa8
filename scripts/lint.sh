#!/usr/bin/env bash
# Lint and synthesis check of rtl/: Verilator --lint-only -Wall on every file (package first) and
# on watkins_top in both shading modes (Phong = 0 and 1), then yosys 0.23: read,
# hierarchy/proc/check of the Phong top (every module) at the synthesis sizes; with --synth a full synth_ice40 of the Gouraud top with small
# buffers (MaxWidth, MaxActiveEdges) and of the two Phong blocks (normalizer, phong_shader) on their
# own, so every module is synthesized in a few minutes; --synth-all also synthesizes the whole
# Phong top (5 more minutes). Fails on any
# warning or error. The only yosys warning tolerated is "Replacing memory ... with list of
# registers": pipeline register arrays (span_reciprocal stages, active-edge banks) are meant to
# be flops, and yosys says so for each one.
# Usage: scripts/lint.sh [--synth | --synth-all]   (CI runs --synth via scripts/test.sh)
set -euo pipefail
cd "$(dirname "$0")/.."

PKG=rtl/watkins_pkg.sv
mapfile -t SRCS < <(ls rtl/*.sv | grep -v "^${PKG}$" | sort)
VLT=()
INC=(-Irtl)  # rtl/watkins_assert.svh (yosys finds includes next to the including file)
[[ -n "$(ls rtl/*.vlt 2>/dev/null)" ]] && VLT=(rtl/*.vlt)
SYNTH_WIDTH=${SYNTH_WIDTH:-16}
SYNTH_EDGES=${SYNTH_EDGES:-4}
LOG=$(mktemp -d)
trap 'rm -rf "$LOG"' EXIT

echo "== verilator --lint-only -Wall"
verilator --lint-only -Wall "${INC[@]}" --top-module watkins_top "${VLT[@]}" "$PKG" "${SRCS[@]}"
verilator --lint-only -Wall "${INC[@]}" --top-module watkins_top -GPhong=1 "${VLT[@]}" "$PKG" "${SRCS[@]}"
# A configuration file's top parameters as `watkins_gen_pkg --params` prints them (built here from
# the sources, as scripts/gen_pkg.sh does, so lint needs no build), Phong dropped (both modes are
# linted).
curved_params() {
  [ -x "$LOG/gen_pkg" ] || g++ -std=c++17 -Imodel/twins -Imodel/prepare -Imodel/scene sim/gen_pkg.cpp \
    model/twins/config.cpp model/prepare/config_file.cpp model/scene/strict_json.cpp -o "$LOG/gen_pkg"
  "$LOG/gen_pkg" --params "$1" --shading phong | grep -v '^-GPhong=' | tr '\n' ' '
}
# The top built for other configurations (as `watkins_gen_pkg --params` prints them): a sized
# one (docs/size/default.*.json: depth without fraction bits, X narrower than the screen index)
# and an odd one (X at the 1/16-pixel minimum, 3-bit depth word, normals finer than the
# normalizer reads), each in both shading modes; and the curved-edge top (EdgeOrder 3,
# docs/size/patches.curves.phong.json's formats; 68 active edges, more than the 64 iterations
# Verilator unrolls by default: active_edge_list's insertion must need no unrolling).
CONFIGS=("-GMaxActiveEdges=36 -GMaxWidth=320 -GXIntBits=9 -GXFracBits=15 -GDepthIntBits=6 -GDepthFracBits=0 -GAttrIntBits=9 -GAttrFracBits=6 -GDepthBits=5 -GPolyIdBits=7 -GMaterialIdBits=1 -GEdgeIdBits=9"
         "-GMaxActiveEdges=5 -GMaxWidth=100 -GXIntBits=8 -GXFracBits=4 -GDepthIntBits=2 -GDepthFracBits=1 -GAttrIntBits=1 -GAttrFracBits=18 -GDepthBits=16 -GPolyIdBits=1 -GMaterialIdBits=3 -GEdgeIdBits=3"
         "$(curved_params docs/size/patches.curves.phong.json)")
for cfg in "${CONFIGS[@]}"; do
  for phong in 0 1; do
    # shellcheck disable=SC2086
    verilator --lint-only -Wall "${INC[@]}" --top-module watkins_top -GPhong=$phong $cfg "${VLT[@]}" "$PKG" "${SRCS[@]}"
  done
done
# Every module on its own as well, so parameters the top does not use are checked too.
for f in "${SRCS[@]}"; do
  m=$(basename "$f" .sv)
  verilator --lint-only -Wall "${INC[@]}" --top-module "$m" "${VLT[@]}" "$PKG" "${SRCS[@]}"
done
# The two blocks with an EdgeOrder of their own, at order 3.
for m in edge_incrementer active_edge_list; do
  verilator --lint-only -Wall "${INC[@]}" --top-module "$m" -GEdgeOrder=3 "${VLT[@]}" "$PKG" "${SRCS[@]}"
done
echo "   clean"

yosys_check() {  # $1: label, $2: script
  local out="$LOG/$1.log"
  if ! yosys -q -l "$out" -p "$2" >/dev/null 2>&1; then
    echo "yosys ($1) failed:"; grep -iE "error|warning" "$out" | head -40; exit 1
  fi
  local bad
  bad=$(grep -iE "^(warning|error)" "$out" | grep -vE "Replacing memory .* with list of registers|^Warnings: [0-9]+ unique messages" || true)
  if [[ -n "$bad" ]]; then echo "yosys ($1) warnings:"; echo "$bad" | head -40; exit 1; fi
}

READ="read_verilog -sv $PKG ${SRCS[*]}"
SMALL="-chparam MaxWidth $SYNTH_WIDTH -chparam MaxActiveEdges $SYNTH_EDGES"
echo "== yosys read + hierarchy/proc/check (Phong top: every module; MaxWidth=$SYNTH_WIDTH, MaxActiveEdges=$SYNTH_EDGES)"
# The buffers as synthesis sizes them (Verilator above lints the defaults): a quick check.
yosys_check elab "$READ; hierarchy -check -top watkins_top $SMALL -chparam Phong 1; proc; check -assert"
# The sized configuration above (yosys takes the same parameters through chparam).
SIZED=$(echo "${CONFIGS[0]}" | sed -E 's/-G([A-Za-z]+)=([0-9]+)/-chparam \1 \2/g')
yosys_check elab_sized "$READ; hierarchy -check -top watkins_top $SIZED -chparam Phong 1; proc; check -assert"
# And the curved-edge top (EdgeOrder 3).
yosys_check elab_cubic "$READ; hierarchy -check -top watkins_top $SMALL -chparam Phong 1 -chparam EdgeOrder 3; proc; check -assert"
echo "   clean"

synth() {  # $1: label, $2: top, $3: hierarchy -chparam options
  echo "== yosys synth_ice40 $2 $3"
  # synth_ice40 up to its final check step, whose first command (autoname, cosmetic renaming) is
  # quadratic in yosys 0.23 and alone takes over 10 minutes here; the rest of that step is run by
  # hand. -dsp maps the multipliers to SB_MAC16 (iCE40 UltraPlus), which keeps ABC's work, and
  # the run, to minutes.
  yosys_check "$1" "$READ; hierarchy -check -top $2 $3; synth_ice40 -dsp -top $2 -run :check; hierarchy -check; check -noinit -assert; tee -o $LOG/$1.txt stat"
  sed -n '/Number of cells/,/^$/p' "$LOG/$1.txt" | head -30
}
if [[ "${1:-}" == --synth* ]]; then
  synth gouraud watkins_top "$SMALL"
  synth normalizer normalizer ""
  synth phong_shader phong_shader ""
  [[ "$1" == --synth-all ]] && synth phong watkins_top "$SMALL -chparam Phong 1"
  echo "   clean"
fi
echo "lint.sh: OK"
