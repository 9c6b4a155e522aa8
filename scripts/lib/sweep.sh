#!/usr/bin/env bash
# Error against cost: `watkins sweep` (scenes × shading: flat, Gouraud eq. 1, Gouraud eq. 2, Phong ×
# tessellation [× fraction bits]; in process; sim/sweep.cpp) writes docs/results/sweep.csv and docs/results/sweep.md,
# then scripts/lib/sweep_plots.py draws error against cycles and against bits (Pareto fronts marked) into
# docs/ and the eq. (1) vs eq. (2) table into docs/results/sweep_eq1_eq2.md; with a --frac-bits axis, error
# against edge-record bits and the crossover table (NAME_crossover.md) instead. The README's plots
# and tables.
#   scripts/lib/sweep.sh                          sphere, cone and the default scene, RTL cycles, all cores
#   scripts/lib/sweep.sh SCENE ... [OPTIONS]      any `watkins sweep` scenes and options except --csv/--md
#   WATKINS_SWEEP_OUT=dir scripts/lib/sweep.sh    write somewhere else than docs/
#   WATKINS_SWEEP_NAME=sweep_frac scripts/lib/sweep.sh SCENE ... --frac-bits 0,1,...,16
#                                          another name than sweep (NAME.csv, NAME.md, NAME_*.png,
#                                          NAME_eq1_eq2.md, NAME_crossover.md): the fraction-bits
#                                          sweep of the README beside the default one
# A large sweep over machines: run `watkins sweep ... --shard $i/$N --csv part$i.csv` per task
# (Slurm array, GNU parallel), then `scripts/lib/sweep_plots.py part*.csv` merges the parts.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build="${WATKINS_BUILD:-$root/build}"
[ -x "$build/watkins" ] || "$root/scripts/setup" --main >/dev/null
out="${WATKINS_SWEEP_OUT:-$root/docs}"
name="${WATKINS_SWEEP_NAME:-sweep}"
mkdir -p "$out"
cd "$root"  # scene paths in the CSV relative to the repository
args=("$@")
[ ${#args[@]} -gt 0 ] || args=(scenes/sphere.json scenes/cone.json scenes/default.json --rtl --jobs "$(nproc)")
echo "machine $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(date -u +%Y-%m-%d)"
"$build/watkins" sweep "${args[@]}" --csv "$out/$name.csv" --md "$out/$name.md"
python3 "$root/scripts/lib/sweep_plots.py" "$out/$name.csv" --out "$out" --prefix "$name" \
  --summary "$out/${name}_eq1_eq2.md" --crossover "$out/${name}_crossover.md"
