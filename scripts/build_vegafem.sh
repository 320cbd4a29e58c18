#!/usr/bin/env bash
# Builds the part of VegaFEM that bench/bench_vegafem.cpp measures (a benchmark peer; BSD-3-Clause, University of
# Southern California) from a git directory brought by the tool library's `fetch` (github:dyollb/VegaFEM), into
# PREFIX (default build/vegafem): PREFIX/lib/libvega.a and PREFIX/include/<library>/*.h. Nothing of Vega is
# committed here and nothing is downloaded.
# Only the sources of the sparse implicit integrator, StVK tets and their support are compiled (-O3 -DNDEBUG, as
# Vega's Release build), without TBB, MKL, PARDISO or SPOOLES: Vega then solves its linear systems by its Jacobi-
# preconditioned CG. Vega's own CMake build is not used: it compiles every library, and its dense integrators call
# LAPACK without the string-length arguments of Debian's lapack.h 3.11, so it does not build here.
# Then: cmake --preset release -DHOOKE_VEGAFEM_DIR=build/vegafem && cmake --build --preset release --target hooke_bench
# Usage: scripts/build_vegafem.sh VEGA_GIT_DIR [PREFIX]
set -euo pipefail
if [ $# -lt 1 ]; then
  echo "usage: $0 VEGA_GIT_DIR [PREFIX]   (VEGA_GIT_DIR: e.g. /work/.mirror/dyollb+VegaFEM/repo)" >&2
  exit 2
fi
git_dir=$1
prefix=$(realpath -m "${2:-build/vegafem}")
rm -rf "$prefix/src" "$prefix/obj" "$prefix/include" "$prefix/lib"
mkdir -p "$prefix/src" "$prefix/obj" "$prefix/include" "$prefix/lib"
# A checkout through a private index: the fetched git directory is only read.
GIT_INDEX_FILE="$prefix/index" git --git-dir="$git_dir" --work-tree="$prefix/src" checkout HEAD -- libraries
rm -f "$prefix/index"
lib=$prefix/src/libraries
: > "$lib/include/vega-config.h"  # no optional dependency
dirs=(basicAlgorithms constrainedDOFs forceModel integrator integratorSparse minivector performanceCounter
  polarDecomposition sparseMatrix stvk volumetricMesh)
sources=("$lib/elasticForceModel/StVKForceModel.cpp" "$lib/sparseSolver/CGSolver.cpp" "$lib/sparseSolver/linearSolver.cpp"
  "$lib/mesh/boundingBox.cpp" "$lib/mesh/geometryQuery.cpp")
for d in "${dirs[@]}"; do sources+=("$lib/$d"/*.cpp); done
includes=()
for d in "$lib"/*/; do includes+=(-I "$d"); done
export prefix
printf '%s\n' "${sources[@]}" | xargs -P "$(nproc)" -I{} sh -c \
  'g++ -std=c++14 -O3 -DNDEBUG -fPIC -w "$@" -c "{}" -o "$prefix/obj/$(echo "{}" | md5sum | cut -c1-12).o"' \
  sh "${includes[@]}"
ar rcs "$prefix/lib/libvega.a" "$prefix"/obj/*.o
for d in "$lib"/*/; do
  name=$(basename "$d")
  mkdir -p "$prefix/include/$name"
  cp "$d"*.h "$prefix/include/$name/" 2>/dev/null || true
done
echo "VegaFEM (git $(git --git-dir="$git_dir" rev-parse --short HEAD)): ${#sources[@]} sources in $prefix/lib/libvega.a"
