#!/usr/bin/env bash
# Installs every Debian package hooke needs. Idempotent: packages already present are skipped.
# Usage: scripts/setup.sh [--meshing] [--bench]
#   (default)  build, test and report dependencies, and the viewer's (GLFW, Dear ImGui, stb, Xvfb)
#              and Dask distributed with pandas (hooke batch, studies beyond one machine)
#              and the real scanned surfaces the meshing tests use (CGAL's sample data in libcgal-demo, not linked)
#              and TetGen's program, run on files by --mesher tetgen (AGPL-3, never linked)
#              and ITK (label images: NIfTI, NRRD, MetaImage) with its example data (a real brain segmentation the
#              label-image tests use)
#   --meshing  also gmsh, needed only to regenerate the committed meshes in data/meshes
#   --bench    also Bullet, a benchmark peer of bench/ (the other, VegaFEM, needs only g++: scripts/build_vegafem.sh)
set -euo pipefail

core=(
  build-essential cmake ninja-build pkg-config ccache clang-format clang-14 libclang-rt-14-dev
  libeigen3-dev libsuitesparse-dev libopenblas0-pthread libtbb-dev libnglib-dev
  libcli11-dev libfmt-dev libspdlog-dev nlohmann-json3-dev libtinyobjloader-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3-dev python3-numpy python3-scipy python3-pytest python3-matplotlib python3-meshio pybind11-dev
  python3-distributed python3-pandas
  libglfw3-dev libimgui-dev libstb-dev xvfb xauth
  libcgal-demo tetgen
  libinsighttoolkit5-dev insighttoolkit5-examples zlib1g-dev
)
extra=()
for arg in "$@"; do
  case "$arg" in
    --meshing) extra+=(gmsh) ;;
    --bench) extra+=(libbullet-dev) ;;
    *) echo "setup.sh: unknown option '$arg'" >&2; exit 2 ;;
  esac
done

wanted=("${core[@]}" "${extra[@]}")
missing=()
for pkg in "${wanted[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$pkg")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup.sh: all ${#wanted[@]} packages present"
  exit 0
fi

echo "setup.sh: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
