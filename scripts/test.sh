#!/usr/bin/env bash
# Sets up, builds and runs every test: the model and RTL tests under ctest, and the RTL lint
# (Verilator -Wall and yosys synth_ice40). This is what CI runs (.ci/run).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="${WATKINS_BUILD:-$root/build}"
"$root/scripts/setup.sh"
if [ -x "$root/scripts/lint.sh" ]; then
  "$root/scripts/lint.sh" --synth
fi
cd "$build"
ctest -j"${WATKINS_JOBS:-2}" --output-on-failure
