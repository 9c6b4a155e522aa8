#!/usr/bin/env bash
# Lint and synthesis check of rtl/: Verilator --lint-only -Wall on every file (package first) and
# on watkins_top in both shading modes (Phong = 0 and 1), without the smoother, and built for
# configuration files (scenes/sized, tests/lint), then yosys 0.23: read,
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
# The top without Herman & Liu's smoother (Smoothing = 0), at the default configuration.
verilator --lint-only -Wall "${INC[@]}" --top-module watkins_top -GSmoothing=0 "${VLT[@]}" "$PKG" "${SRCS[@]}"
# A configuration file's top parameters as `watkins_gen_pkg --params F --shading S` prints them
# (built here from the sources, as scripts/gen_pkg.sh does, so lint needs no build; Phong
# included).
top_params() {  # $1: configuration file, $2: gouraud | phong
  [ -x "$LOG/gen_pkg" ] || g++ -std=c++17 -Imodel/twins -Imodel/prepare -Imodel/scene sim/gen_pkg.cpp \
    model/twins/config.cpp model/prepare/config_file.cpp model/scene/strict_json.cpp -o "$LOG/gen_pkg"
  local p
  p=$("$LOG/gen_pkg" --params "$1" --shading "$2" | tr '\n' ' ')
  [ -n "$p" ] || { echo "lint.sh: no parameters from $1" >&2; exit 1; }
  echo "$p"
}
# The top built for other configurations, read from their files (FILE@shading): the sized default
# scene (scenes/sized/default.*.json: depth without fraction bits, X narrower than the screen index,
# no smoother: Smoothing = 0), an odd one (tests/lint/odd.json: X at the 1/16-pixel minimum, 3-bit
# depth word, normals finer than the normalizer reads) in both shading modes, and the curved-edge
# top (EdgeOrder 3, scenes/sized/patches.curves.phong.json; 68 active edges, more than the 64 iterations Verilator
# unrolls by default: active_edge_list's insertion must need no unrolling), both modes.
LINT_TOPS=(scenes/sized/default.gouraud.json@gouraud scenes/sized/default.phong.json@phong
           tests/lint/odd.json@gouraud tests/lint/odd.json@phong
           scenes/sized/patches.curves.phong.json@gouraud scenes/sized/patches.curves.phong.json@phong)
for top in "${LINT_TOPS[@]}"; do
  cfg=$(top_params "${top%@*}" "${top#*@}")
  # shellcheck disable=SC2086
  verilator --lint-only -Wall "${INC[@]}" --top-module watkins_top $cfg "${VLT[@]}" "$PKG" "${SRCS[@]}"
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
# The sized Phong top above (yosys takes the same parameters through chparam).
SIZED=$(top_params scenes/sized/default.phong.json phong | sed -E 's/-G([A-Za-z]+)=([0-9]+)/-chparam \1 \2/g')
yosys_check elab_sized "$READ; hierarchy -check -top watkins_top $SIZED; proc; check -assert"
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
