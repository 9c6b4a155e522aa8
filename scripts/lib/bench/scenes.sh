#!/usr/bin/env bash
# The rule that the double reference is never faster than the bit-exact model: both on
# every shipped scene (scenes/*.json) in both shadings, each pair measured back to back by one
# watkins_bench run (0.3 s per measurement). One line per scene and shading, then the summary
# (how many pairs hold, and the closest one). Skipped when scripts/bench was given a scene.
#   scripts/lib/bench/scenes.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/../../.." && pwd)
build="${WATKINS_BUILD:-$root/build}"
[ $# -eq 0 ] || [ -z "${1:-}" ] || exit 0
held=0 total=0 closest="" closest_ratio=""
for scene in "$root"/scenes/*.json; do
  for shading in gouraud phong; do
    out=$("$build/watkins_bench" "$scene" --shading "$shading" --seconds 0.3)
    m=$(echo "$out" | sed -n 's/^fixed-point model .* \([0-9.]*\) M fragments\/s .*/\1/p' | head -1)
    d=$(echo "$out" | sed -n 's/^double reference .* \([0-9.]*\) M fragments\/s.*/\1/p' | head -1)
    name="$(basename "$scene" .json) $shading"
    ratio=$(awk -v m="$m" -v d="$d" 'BEGIN { printf "%.2f", (d > 0) ? m / d : 0 }')
    printf "shipped scene       %-28s model %8s M fragments/s, double reference %8s M (%sx)\n" "$name" "$m" "$d" "$ratio"
    total=$((total + 1))
    if awk -v r="$ratio" 'BEGIN { exit !(r >= 1) }'; then held=$((held + 1)); fi
    if [ -z "$closest_ratio" ] || awk -v r="$ratio" -v c="$closest_ratio" 'BEGIN { exit !(r < c) }'; then
      closest="$name" closest_ratio="$ratio"
    fi
  done
done
echo "shipped scenes      model at least as fast as the double reference on $held of $total (scene, shading); closest $closest ${closest_ratio}x"
