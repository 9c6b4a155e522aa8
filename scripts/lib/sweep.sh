#!/usr/bin/env bash
# Error against cost: `watkins sweep` (scenes × shading: flat, Gouraud eq. 1, Gouraud eq. 2, Phong ×
# tessellation [× fraction bits]; every point rendered in process by the fixed-point model, the
# double reference and the analytic truth; sim/sweep.cpp), then scripts/lib/sweep_plots.py for the
# plots and the derived tables. Writes into docs/results/:
#   scripts/lib/sweep.sh          sweep.csv, sweep.md (plots and the table), sweep_eq1_eq2.md,
#                                 images/sweep_{mean,max}_{cycles,bits}.png: sphere, cone and the
#                                 default scene at 0.5, 1, 2 and 4 times their tessellation
#   scripts/lib/sweep.sh --frac   sweep_frac.csv, sweep_frac.md, sweep_frac_crossover.md,
#                                 images/sweep_frac_*_erbits.png: the same scenes at 0.5, 1 and 2
#                                 times, the shading's attribute fraction bits from 0 to 16
#   scripts/lib/sweep.sh NAME SCENE ... [OPTIONS]   any `watkins sweep` scenes and options (not
#                                 --csv/--md) into NAME.csv, NAME.md, ...
# WATKINS_RESULTS_DIR replaces docs/results; WATKINS_JOBS the threads (default: every core).
# A large sweep over machines: run `watkins sweep ... --shard $i/$N --csv part$i.csv` per task
# (Slurm array, GNU parallel), then `scripts/lib/sweep_plots.py part*.csv` merges the parts.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build="${WATKINS_BUILD:-$root/build}"
results="${WATKINS_RESULTS_DIR:-$root/docs/results}"
jobs="${WATKINS_JOBS:-$(nproc)}"
[ -x "$build/watkins" ] || "$root/scripts/setup" --main >/dev/null
# shellcheck source=results_header.sh
source "$root/scripts/lib/results_header.sh"
scenes=(scenes/sphere.json scenes/cone.json scenes/default.json)
case "${1:-}" in
  "") name=sweep; args=("${scenes[@]}" --tess 0.5,1,2,4) ;;
  --frac) name=sweep_frac; args=("${scenes[@]}" --tess 0.5,1,2 --frac-bits 0,1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16) ;;
  -*) echo "sweep.sh: unknown option $1 (--frac, or NAME SCENE ... [OPTIONS])" >&2; exit 2 ;;
  *) name=$1; shift; args=("$@") ;;
esac
head=$(results_header "${RESULTS_COMMAND:-scripts/lib/sweep.sh${*:+ $*}}")
mkdir -p "$results/images"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$root"  # scene paths in the CSV relative to the repository
"$build/watkins" sweep "${args[@]}" --jobs "$jobs" --quiet --csv "$results/$name.csv" --md "$tmp/table.md"
python3 "$root/scripts/lib/sweep_plots.py" "$results/$name.csv" --out "$results/images" --prefix "$name" \
  --summary "$tmp/eq1_eq2.md" --crossover "$tmp/crossover.md" >/dev/null
command="watkins sweep ${args[*]}"

if [ "$name" = sweep_frac ] || [ -s "$tmp/crossover.md" ]; then
  {
    echo "$head"
    echo
    echo "# Error against fraction bits"
    echo
    echo "\`$command\`: the fraction bits of the shading's attribute group (the shade R, G, B for flat"
    echo "and Gouraud, in 8-bit levels; the normal Nx, Ny, Nz for Phong, in units of 1.0) from 0 to 16,"
    echo "X and depth at 16. Integer bits are not an axis: each point's configuration has exactly the"
    echo "integer bits its scene needs at those fractions. Each fraction bit of the shade costs six"
    echo "edge-record bits (value and slope of R, G and B). Errors are in 8-bit levels; every column"
    echo "is in [$name.csv]($name.csv), the default sweep in [sweep.md](sweep.md)."
    echo
    echo "Where the quantization meets the algorithm's own error, per scene, shading and"
    echo "tessellation: [${name}_crossover.md](${name}_crossover.md)."
    echo
    echo "Error against the edge-record bits of each point's configuration; one dashed Pareto front"
    echo "per shading, labelled with the attribute's fraction bits; y on a symmetric log scale,"
    echo "linear below 0.01 level:"
    echo
    for e in "double_mean|mean error against the double reference" "truth_mean|mean error against the truth" \
             "double_max|max error against the double reference" "truth_max|max error against the truth"; do
      echo "![${e#*|}, against edge-record bits](images/${name}_${e%%|*}_erbits.png)"
    done
    echo
    cat "$tmp/table.md"
  } > "$results/$name.md"
  {
    echo "$head"
    echo
    echo "# Where the quantization equals the algorithm's error"
    echo
    echo "Per scene, shading and tessellation: the attribute fraction width at which the model's mean"
    echo "error against the double reference (the quantization) equals the double reference's mean"
    echo "error against the analytic truth (the algorithm's own error), interpolated on a log scale"
    echo "of the error between the two widths swept that bracket it. From [$name.csv]($name.csv)."
    echo
    cat "$tmp/crossover.md"
  } > "$results/${name}_crossover.md"
  echo "sweep.sh: wrote $name.csv, $name.md, ${name}_crossover.md and images/${name}_*.png in $results"
else
  {
    echo "$head"
    echo
    echo "# Error against cycles and bits"
    echo
    echo "\`$command\`: every point rendered in process by the fixed-point model, the double reference"
    echo "and the analytic truth, with its cycles per frame from the cycle model (equal to the RTL's:"
    echo "[verify.md](verify.md)). Shadings: **flat** (one shade per polygon: the vertex rule at its"
    echo "centroid and plane normal), **gouraud-eq1** and **gouraud-eq2** (Gouraud's pipeline: eq. 1"
    echo "interpolates each vertex's shade; eq. 2 interpolates S·Z and Z and divides per pixel in the"
    echo "shade divider), **phong**; all under Phong's"
    echo "illumination (eq. 3), so the truth applies. Tessellation: the scene's first object's u and v"
    echo "times each factor. Errors in 8-bit levels over pixels showing the same object as the"
    echo "truth; Mach is the largest jump of the first difference of (image − truth) across a polygon"
    echo "edge. Each point runs the configuration its scene needs at 16 fraction bits in every group"
    echo "(fewer bits: [sweep_frac.md](sweep_frac.md)). Every column is in [$name.csv]($name.csv)."
    echo
    echo "Circled: the Pareto front, no other point both cheaper and better. \"Bits\" is the active-edge"
    echo "list the scene needs: active edges × the edge record of the point's configuration."
    echo
    for e in mean max; do
      echo "![$e error against cycles](images/${name}_${e}_cycles.png)"
      echo "![$e error against bits](images/${name}_${e}_bits.png)"
      echo
    done
    echo "Gouraud's eq. (1) against eq. (2), both against the truth: [${name}_eq1_eq2.md](${name}_eq1_eq2.md)."
    echo
    cat "$tmp/table.md"
  } > "$results/$name.md"
  {
    echo "$head"
    echo
    echo "# Gouraud's eq. (1) against eq. (2)"
    echo
    echo "Eq. (1) interpolating each vertex's shade, eq. (2) interpolating S·Z and Z and dividing per"
    echo "pixel (the shade divider), both against the analytic truth, per scene and tessellation; the"
    echo "deep scenes where the two part most are in [gouraud_eq2.md](gouraud_eq2.md). From"
    echo "[$name.csv]($name.csv)."
    echo
    cat "$tmp/eq1_eq2.md"
  } > "$results/${name}_eq1_eq2.md"
  echo "sweep.sh: wrote $name.csv, $name.md, ${name}_eq1_eq2.md and images/${name}_*.png in $results"
fi
