#!/usr/bin/env bash
# ctest fusesoc_core (label fusesoc): fusesoc accepts watkins.core. Its lint target (Verilator
# -Wall) passes on the Gouraud and the Phong top, and its synth target sets up a yosys
# synth_ice40 -dsp run of the top (running it takes minutes; scripts/lint --synth synthesizes
# the tops in CI), its ulx3s target sets up the board top's trellis flow and its icebreaker
# target the iCEBreaker top's icestorm flow. About 50 s.
#   check.sh SOURCE_DIR WORK_DIR
set -euo pipefail
src=$1 work=$2
command -v fusesoc >/dev/null || { echo "fusesoc_core: fusesoc not installed (scripts/setup installs it with pip)"; exit 1; }
rm -rf "$work"
core=watkins:shading:pipeline
for phong in 0 1; do
  fusesoc --cores-root "$src" run --build-root "$work/lint$phong" --target lint "$core" --Phong=$phong
done
fusesoc --cores-root "$src" run --build-root "$work/synth" --setup --target synth "$core" --Phong=1
# The generated yosys script must synthesize the Phong top for iCE40 with the DSPs.
procs=$(ls "$work"/synth/*/synth-icestorm/edalize_yosys_procs.tcl)
grep -q "synth_ice40 -dsp -top" "$procs" || { echo "fusesoc_core: synth target does not run synth_ice40 -dsp"; exit 1; }
grep -q "chparam -set Phong 1 watkins_top" "$procs" || { echo "fusesoc_core: --Phong=1 did not reach watkins_top"; exit 1; }
# The board target: edalize's trellis flow set up for ulx3s_top with the board's pins, the bank
# file and the ECP5 define reaching yosys.
echo 0 > "$work/bank.hex"
fusesoc --cores-root "$src" run --build-root "$work/ulx3s" --setup --target ulx3s "$core" --BankFile="$work/bank.hex"
dir=$(ls -d "$work"/ulx3s/*/ulx3s-trellis)
grep -q "synth_ecp5 *-top" "$dir/edalize_yosys_procs.tcl" || { echo "fusesoc_core: ulx3s target does not run synth_ecp5"; exit 1; }
grep -q "chparam -set BankFile {\"$work/bank.hex\"} ulx3s_top" "$dir/edalize_yosys_procs.tcl" ||
  { echo "fusesoc_core: --BankFile did not reach ulx3s_top"; exit 1; }
grep -q "WATKINS_ECP5" "$dir/edalize_yosys_procs.tcl" || { echo "fusesoc_core: WATKINS_ECP5 is not defined"; exit 1; }
grep -q -- "--lpf .*ulx3s_top.lpf" "$dir/Makefile" || { echo "fusesoc_core: nextpnr-ecp5 does not get the board's pins"; exit 1; }
grep -q "ecppack" "$dir/Makefile" || { echo "fusesoc_core: no ecppack step"; exit 1; }
# The iCEBreaker target: edalize's icestorm flow set up for icebreaker_top (compact) with the
# board's pins and the scene's flash address reaching yosys, nextpnr-ice40 for the UP5K in its
# SG48 package, icepack.
fusesoc --cores-root "$src" run --build-root "$work/icebreaker" --setup --target icebreaker "$core" --FlashAddress=131072
dir=$(ls -d "$work"/icebreaker/*/icebreaker-icestorm)
grep -q "synth_ice40 -dsp *-top" "$dir/edalize_yosys_procs.tcl" || { echo "fusesoc_core: icebreaker target does not run synth_ice40 -dsp"; exit 1; }
grep -q "chparam -set FlashAddress 131072 icebreaker_top" "$dir/edalize_yosys_procs.tcl" ||
  { echo "fusesoc_core: --FlashAddress did not reach icebreaker_top"; exit 1; }
grep -q "chparam -set Compact 1 icebreaker_top" "$dir/edalize_yosys_procs.tcl" ||
  { echo "fusesoc_core: Compact=1 did not reach icebreaker_top"; exit 1; }
grep -q -- "--up5k --package sg48 --pcf .*icebreaker_top.pcf" "$dir/Makefile" ||
  { echo "fusesoc_core: nextpnr-ice40 does not get the UP5K, its package and the board's pins"; exit 1; }
grep -q "icepack" "$dir/Makefile" || { echo "fusesoc_core: no icepack step"; exit 1; }
echo "fusesoc_core: OK"
