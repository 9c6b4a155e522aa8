#!/usr/bin/env bash
# README figures for crease-angle normals on the portico (issue 13): scenes/portico.json with the
# portico's normals exact (no key) and from the crease rule at 0 / 80 / 180 degrees
# ("crease_angle_deg" on the portico object; the floor keeps its exact normals), each through
# both pipelines (Gouraud: the "phong" vertex rule interpolated; Phong: eq. (3) per pixel).
# Writes docs/portico_crease<A>_<shading>.png (A = 0, 80, 180) and prints, per image: the
# error against the analytic truth (the exact surfaces ray-cast: what the normals and the
# algorithm cost) of the double reference and of the fixed-point model (max, mean, pixels more
# than 1 level off), the hardware needs (polygons after culling, edge records, active edges at
# most on a scan line) and the cycles per frame the cycle model predicts for the RTL (full-frame
# and sparse output). Then the STL import against the built-in bay: scenes/vault_bay.json and
# the same scene reading scenes/vault_bay.stl, both at crease 0 and both at crease 80, and the
# pixels that differ.
#   scripts/lib/vault_figures.sh [OUTDIR]   (default: docs)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build="${WATKINS_BUILD:-$root/build}"
out="${1:-$root/docs}"
[ -x "$build/watkins" ] || "$root/scripts/setup" >/dev/null
mkdir -p "$out"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vault_figures.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

# The scene with `key` added to the object matching `pattern` (the scene files keep each object
# on one line from "type" to its first key after "springing" / "max_edge_length").
with_key() {  # scene pattern key out
  sed "s|$2|$2$3|" "$1" > "$4"
  [ -z "$3" ] || grep -qF -- "$2$3" "$4" || { echo "vault_figures: no match for $2 in $1" >&2; exit 1; }
}

echo "machine $(nproc) cores, $(date -u +%Y-%m-%d); model only (cycles: the cycle model's prediction for the RTL)"
printf "%-6s %-8s | %-22s | %-22s | %8s %8s %6s | %8s %8s\n" "" "" "double vs truth" "fixed vs truth" "" "edge" "active" \
  "cycles" "cycles"
printf "%-6s %-8s | %4s %7s %9s | %4s %7s %9s | %8s %8s %6s | %8s %8s\n" crease shading max mean ">1 px" max mean ">1 px" \
  polygons records edges full sparse
portico='"springing": 4, "u": 10, "v": 1,'
for crease in exact 0 80 180; do
  key=""
  [ "$crease" = exact ] || key=" \"crease_angle_deg\": $crease,"
  scene="$tmp/portico_crease$crease.json"
  with_key "$root/scenes/portico.json" "$portico" "$key" "$scene"
  for shading in gouraud phong; do
    # The exact-normal images are docs/portico_<shading>.png (scripts/lib/phong_figures.sh).
    png="$out/portico_crease${crease}_$shading.png"
    [ "$crease" = exact ] && png="$tmp/exact.png"
    r=$("$build/watkins" render "$scene" --shading $shading --rule phong --out "$png" \
        --truth "$tmp/truth.png")
    read -r td_max td_mean td_over < <(echo "$r" |
      sed -n 's/^vs truth *double reference: max |d| \([0-9]*\) levels, mean |d| \([0-9.]*\) levels, \([0-9]*\) pixels > 1 level.*/\1 \2 \3/p')
    read -r tf_max tf_mean tf_over < <(echo "$r" |
      sed -n 's/^vs truth *fixed model: max |d| \([0-9]*\) levels, mean |d| \([0-9.]*\) levels, \([0-9]*\) pixels > 1 level.*/\1 \2 \3/p')
    polys=$(echo "$r" | sed -n 's/^polygons *\([0-9]*\).*/\1/p')
    records=$(echo "$r" | sed -n 's/^edge records *\([0-9]*\).*/\1/p')
    active=$(echo "$r" | sed -n 's/^needs *active edges \([0-9]*\).*/\1/p')
    read -r full sparse < <(echo "$r" | sed -n 's/^predicted *\([0-9]*\) cycles (full-frame), \([0-9]*\) cycles (sparse).*/\1 \2/p')
    printf "%-6s %-8s | %4s %7s %9s | %4s %7s %9s | %8s %8s %6s | %8s %8s\n" "$crease" $shading "$td_max" "$td_mean" \
      "$td_over" "$tf_max" "$tf_mean" "$tf_over" "$polys" "$records" "$active" "$full" "$sparse"
  done
done

# STL import against the built-in bay: the same camera and light, the portico object replaced by
# a mesh object reading the exported file, the same crease angle on both sides.
echo
echo "STL import (scenes/vault_bay.stl) against the built-in bay (scenes/vault_bay.json), fixed model:"
bay='"max_edge_length": 1,'
for crease in 0 80; do
  with_key "$root/scenes/vault_bay.json" "$bay" " \"crease_angle_deg\": $crease," "$tmp/builtin.json"
  sed "s|{\"type\": \"portico\".*|{\"type\": \"mesh\", \"file\": \"$root/scenes/vault_bay.stl\", \"crease_angle_deg\": $crease, |" \
    "$root/scenes/vault_bay.json" > "$tmp/stl.json"
  for shading in gouraud phong; do
    "$build/watkins" render "$tmp/builtin.json" --shading $shading --out "$tmp/builtin.png" >/dev/null
    "$build/watkins" render "$tmp/stl.json" --shading $shading --out "$tmp/stl.png" >/dev/null
    if cmp -s "$tmp/builtin.png" "$tmp/stl.png"; then
      echo "  crease $crease, $shading: identical images"
    else
      python3 -W ignore - "$tmp/builtin.png" "$tmp/stl.png" "$crease" "$shading" <<'EOF' || echo "  crease $3, $4: images differ"
import sys
from PIL import Image
a, b = (Image.open(p).convert("RGB") for p in sys.argv[1:3])
d = [max(abs(x - y) for x, y in zip(p, q)) for p, q in zip(a.getdata(), b.getdata())]
print(f"  crease {sys.argv[3]}, {sys.argv[4]}: {sum(v > 0 for v in d)} pixels differ, "
      f"{sum(v > 1 for v in d)} by more than 1 level, max {max(d)} levels")
EOF
    fi
  done
done
echo "images in $out"
