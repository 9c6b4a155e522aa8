#!/usr/bin/env bash
# Writes docs/results/whitted.md (part `whitted` of scripts/results): Whitted's curved patches
# against tessellated Gouraud (eq. 1, Phong's eq. (3) at the vertices) and Phong at the same cells.
# One `watkins sweep` in process over the patch, the B-spline sheet and the teapot, with u = v = n
# polygon cells per patch for Gouraud and Phong and k_u = k_v = n subpatches per patch for
# Whitted's curves (Phong pipeline, edge_order 3), each point against the analytic truth, cycles
# from the cycle model, into docs/results/whitted_compare.csv (every column of every point);
# scripts/lib/whitted_figures.py turns it into the table, the findings and
# the montages docs/results/images/whitted_{teapot,patch}.png (truth | Gouraud | Phong | Whitted,
# rows n = 2 and 4). Then the three patch scenes drawn by curves through the RTL at the order-3
# configuration scenes/sized/patches.curves.phong.json (full-frame; the teapot also sparse and
# sparse under input gaps and output stalls).
#   scripts/lib/whitted_figures.sh [OUTDIR]   (default: $WATKINS_RESULTS_DIR or docs/results; images in OUTDIR/images)
#   WATKINS_WHITTED_UV=2,4,8,16   the n of the sweep
#   WATKINS_NO_RTL=1              the sweep only (no RTL table)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
uv="${WATKINS_WHITTED_UV:-2,4,8,16}"
# shellcheck source=results_header.sh
source "$root/scripts/lib/results_header.sh"
results_begin whitted_figures "${1:-}"
cd "$root"  # scene paths in the sweep relative to the repository

mkdir "$tmp/images"
"$build/watkins" sweep scenes/patch.json scenes/bspline.json scenes/teapot.json \
  --shadings gouraud-eq1,phong,whitted --uv "$uv" --jobs "$(nproc)" -q \
  --csv "$out/whitted_compare.csv" --images "$tmp/images"

rtl=()
if [ -z "${WATKINS_NO_RTL:-}" ]; then
  cfg=scenes/sized/patches.curves.phong.json
  for scene in patch bspline teapot; do
    "$build/watkins" render "scenes/$scene.json" --patches curves --shading phong --rtl --config "$cfg" \
      --out "$tmp/rtl.png" > "$tmp/rtl_${scene}_full.txt"
    rtl+=(--rtl "$scene:full-frame:$tmp/rtl_${scene}_full.txt")
  done
  "$build/watkins" render scenes/teapot.json --patches curves --shading phong --rtl --config "$cfg" --sparse \
    --out "$tmp/rtl.png" > "$tmp/rtl_teapot_sparse.txt"
  "$build/watkins" render scenes/teapot.json --patches curves --shading phong --rtl --config "$cfg" --sparse \
    --gap 0.2 --stall 0.3 --out "$tmp/rtl.png" > "$tmp/rtl_teapot_stalls.txt"
  rtl+=(--rtl "teapot:sparse:$tmp/rtl_teapot_sparse.txt"
        --rtl "teapot:sparse, gaps 0.2, stalls 0.3:$tmp/rtl_teapot_stalls.txt")
fi

py=python3  # one with matplotlib (the montages), else /usr/bin's
"$py" -c 'import matplotlib' 2>/dev/null || { [ -x /usr/bin/python3 ] && py=/usr/bin/python3; }
"$py" "$root/scripts/lib/whitted_figures.py" "$out/whitted_compare.csv" --images "$tmp/images" \
  --md "$tmp/whitted.md" --montage teapot:2,4 --montage patch:2,4 --out "$out/images" \
  --header "$(results_header "scripts/results whitted")" --uv "$uv" "${rtl[@]}" \
  --seconds "$(( $(date +%s) - start ))"
mv "$tmp/whitted.md" "$out/whitted.md"
echo "wrote $out/whitted.md, images in $out/images"
