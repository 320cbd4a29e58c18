#!/usr/bin/env bash
# Installs a built hooke into a temporary prefix and builds examples/calibrate_and_simulate against the installed
# package twice, with find_package(hooke CONFIG) and with pkg-config, never against the build tree; runs both; and
# imports the installed Python package from the prefix.
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
# The Python package from the same prefix (the folder /usr/bin/python3 searches under /usr).
site=$(/usr/bin/python3 -c 'import sys; print(f"lib/python{sys.version_info[0]}.{sys.version_info[1]}/dist-packages")')
if [ -d "$tmp/prefix/$site/hooke" ]; then
  PYTHONPATH="$tmp/prefix/$site" /usr/bin/python3 -c "
import hooke
m = hooke.calibrate(hooke.read_mesh('data/meshes/cylinder.msh'), hooke.Material(14630.0, 0.25))
assert m.pairs.shape[0] > 0 and hooke.__file__.startswith('$tmp/prefix'), hooke.__file__
print('check_install.sh: import hooke from the prefix:', m)"
else
  echo "check_install.sh: the Python package is missing from $tmp/prefix/$site" >&2
  exit 1
fi
echo "check_install.sh: the installed package builds and runs with CMake and with pkg-config"
