#!/usr/bin/env bash
# The same RTL under Icarus Verilog, for comparison with Verilator. Icarus 11 cannot read the
# package's packed structs, so yosys elaborates the SystemVerilog to plain Verilog first
# (read_verilog -sv; proc; flatten; write_verilog) and Icarus simulates that, checking every
# pixel against the model. Prints simulated cycles per second.
#   scripts/lib/bench/icarus.sh [SCENE]
set -euo pipefail
root=$(cd "$(dirname "$0")/../../.." && pwd)
build="${WATKINS_BUILD:-$root/build}"
command -v iverilog >/dev/null && command -v yosys >/dev/null || { echo "icarus: iverilog or yosys missing"; exit 0; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$build/watkins_export" "$@" --dir "$work" >/dev/null
width=$(( 16#$(sed -n 1p "$work/frame.hex") ))
sources=("$root/rtl/watkins_pkg.sv")
for f in "$root"/rtl/*.sv; do [[ "$f" == *watkins_pkg.sv ]] || sources+=("$f"); done
t0=$(date +%s.%N)
yosys -q -p "read_verilog -sv -DSYNTHESIS ${sources[*]}; chparam -set MaxWidth $width watkins_top; \
  hierarchy -top watkins_top; proc; flatten; opt_clean; write_verilog -noattr $work/top.v" \
  >"$work/yosys.log" 2>&1
# The bench's sizes from the one source of formats (model/twins/formats.hpp, as rtl/watkins_pkg.sv).
sizes=()
for name in EdgeRecordBits LineBits UnitBits MaterialIdBits MaterialBits ShininessBits; do
  sizes+=("-Ptb_watkins.$name=$("$build/watkins_gen_pkg" --value "$name")")
done
iverilog -g2012 "${sizes[@]}" -o "$work/tb.vvp" "$work/top.v" "$root/testbench/icarus/tb_watkins.sv"
t1=$(date +%s.%N)
out=$(vvp -n "$work/tb.vvp" +dir="$work" | grep -v "WARNING\|\$finish")
t2=$(date +%s.%N)
echo "$out" | sed 's/^/                    /' | sed '1s/^ */icarus (via yosys)  /'
cycles=$(echo "$out" | sed -n 's/^icarus: \([0-9]*\) cycles.*/\1/p')
awk -v c="$cycles" -v a="$t0" -v b="$t1" -v e="$t2" \
  'BEGIN { printf "icarus speed        %.0f cycles/s (simulation %.1f s; yosys + iverilog elaboration %.1f s)\n", c / (e - b), e - b, b - a }'
