#!/usr/bin/env bash
# Installs a built hooke into a temporary prefix and builds examples/calibrate_and_simulate against the installed
# package twice, with find_package(hooke CONFIG) and with pkg-config, never against the build tree; runs both.
# Usage: scripts/check_install.sh BUILD_DIR
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:?usage: scripts/check_install.sh BUILD_DIR}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" > /dev/null
cmake -S examples/calibrate_and_simulate -B "$tmp/example" -G Ninja -DCMAKE_PREFIX_PATH="$tmp/prefix" \
  -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$tmp/example" > /dev/null
"$tmp/example/calibrate_and_simulate" data/meshes/cylinder.msh 14630 0.25 | tee "$tmp/cmake.out"
export PKG_CONFIG_PATH="$tmp/prefix/lib/pkgconfig"
# shellcheck disable=SC2046
g++ -O2 examples/calibrate_and_simulate/main.cpp -o "$tmp/pc_example" $(pkg-config --cflags --libs hooke)
"$tmp/pc_example" data/meshes/cylinder.msh 14630 0.25 > "$tmp/pc.out"
grep -q "tip node" "$tmp/cmake.out"
cmp "$tmp/cmake.out" "$tmp/pc.out"
echo "check_install.sh: the installed package builds and runs with CMake and with pkg-config"
