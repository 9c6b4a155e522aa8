#!/usr/bin/env bash
# README figures for Phong against Gouraud shading: renders the sphere, cone, highlight and portico scenes
# with both pipelines on the RTL (Gouraud: the "phong" vertex rule, i.e. Phong's eq. (3) at the
# vertices, interpolated; Phong: eq. (3) per pixel on the interpolated, normalized normal),
# writes docs/<scene>_<shading>.png (and docs/<scene>_truth.png, the exact surface, where the
# scene has one) and prints, per image, the RTL's cycles per frame (full-frame
# and sparse output), RTL-vs-model mismatches, the fixed-point error against the double
# reference of the same algorithm (over pixels showing the same polygon: what quantization
# costs), and the double reference's error against the analytic truth (the exact surface
# ray-cast, eq. (3) per pixel, over pixels showing the same object: what the algorithm costs).
#   scripts/lib/phong_figures.sh [OUTDIR]   (default: docs)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build="${WATKINS_BUILD:-$root/build}"
out="${1:-$root/docs}"
[ -x "$build/watkins" ] || "$root/scripts/setup" >/dev/null
mkdir -p "$out"
echo "machine $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(date -u +%Y-%m-%d)"
printf "%-10s %-8s %8s %8s %6s | %-26s | %-26s\n" "" "" "RTL" "RTL" "" "fixed vs double" "double vs analytic truth"
printf "%-10s %-8s %8s %8s %6s | %5s %7s %12s | %5s %7s %12s\n" scene shading cycles sparse "rtl!=m" max mean ">1 of px" max mean ">1 of px"
for scene in sphere cone highlight portico; do
  for shading in gouraud phong; do
    png="$out/${scene}_${shading}.png"
    # highlight is a mesh: no closed form, and --truth of a scene without one is an error.
    truth=(--truth "$out/${scene}_truth.png")
    [ "$scene" = highlight ] && truth=()
    full=$("$build/watkins" render "$root/scenes/$scene.json" --shading $shading --rule phong --rtl --out "$png" \
           "${truth[@]}")
    sparse=$("$build/watkins" render "$root/scenes/$scene.json" --shading $shading --rule phong --rtl --sparse \
             --out "$(mktemp -u).png")
    cyc=$(echo "$full" | sed -n 's/^rtl cycles *\([0-9]*\).*/\1/p')
    scyc=$(echo "$sparse" | sed -n 's/^rtl cycles *\([0-9]*\).*/\1/p')
    mism=$(( $(echo "$full" | sed -n 's/^rtl vs model *\([0-9]*\) mismatching.*/\1/p') +
             $(echo "$sparse" | sed -n 's/^rtl vs model *\([0-9]*\) mismatching.*/\1/p') ))
    read -r dmax dmean over n < <(echo "$full" |
      sed -n 's/^vs double *max |d| \([0-9]*\) levels, mean |d| \([0-9.]*\) levels, \([0-9]*\) pixels > 1 level (over \([0-9]*\) pixels.*/\1 \2 \3 \4/p')
    read -r tmax tmean tover tn < <(echo "$full" |
      sed -n 's/^vs truth *double reference: max |d| \([0-9]*\) levels, mean |d| \([0-9.]*\) levels, \([0-9]*\) pixels > 1 level (over \([0-9]*\) pixels.*/\1 \2 \3 \4/p') ||
      true
    [ -n "${tn:-}" ] && tpx="$tover/$tn" || tpx="-"
    printf "%-10s %-8s %8s %8s %6s | %5s %7s %12s | %5s %7s %12s\n" "$scene" "$shading" "$cyc" "$scyc" "$mism" \
      "$dmax" "$dmean" "$over/$n" "${tmax:--}" "${tmean:--}" "$tpx"
  done
done
echo "images in $out"
