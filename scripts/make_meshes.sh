#!/usr/bin/env bash
# Regenerates the committed meshes (data/meshes) and the reader-test files made by other tools (tests/data).
# Needs the meshing packages: scripts/setup.sh --meshing. Deterministic: Gmsh runs single-threaded (-nt 1).
set -euo pipefail
cd "$(dirname "$0")/.."
g() { gmsh -nt 1 "$@" > /dev/null; }

# The papers' objects (sizes chosen to approach the node and element counts Lloyd et al. 2007 report).
g -3 -format msh41 data/meshes/cylinder.geo -o data/meshes/cylinder.msh
g -3 -format msh41 data/meshes/cylinder_hole.geo -o data/meshes/cylinder_hole.msh
g -3 -format msh41 data/meshes/cone.geo -o data/meshes/cone.msh
g -2 -format msh41 data/meshes/sphere.geo -o data/meshes/sphere_surface.msh
g -2 -format msh41 data/meshes/rectangle_tri.geo -o data/meshes/rectangle_tri.msh

# Reader tests: the same small meshes in every Gmsh flavour, TetGen output, and meshio conversions.
d=tests/data
g -3 -format msh22 $d/box.geo -o $d/gmsh_box_v22_ascii.msh
g -3 -format msh22 -bin $d/box.geo -o $d/gmsh_box_v22_binary.msh
g -3 -format msh41 $d/box.geo -o $d/gmsh_box_v41_ascii.msh
g -3 -format msh41 -bin $d/box.geo -o $d/gmsh_box_v41_binary.msh
g -2 -format msh41 $d/square.geo -o $d/gmsh_square_v41_ascii.msh
g -2 -format msh22 -bin -setnumber quads 1 $d/square.geo -o $d/gmsh_square_quads_v22_binary.msh
tmp=$(mktemp -d)
cp $d/cube.off "$tmp/cube.off"
tetgen -pqQ "$tmp/cube.off"
for ext in node ele face; do cp "$tmp/cube.1.$ext" "$d/tetgen_cube.1.$ext"; done
rm -rf "$tmp"
/usr/bin/python3 - <<'PY'
import meshio
d = "tests/data"
s = meshio.read("data/meshes/sphere_surface.msh")
tri = meshio.Mesh(s.points, [("triangle", s.get_cells_type("triangle"))])
meshio.write(f"{d}/meshio_sphere.stl", tri, binary=True)
meshio.write(f"{d}/meshio_sphere_ascii.stl", tri, binary=False)
meshio.write(f"{d}/meshio_sphere.obj", tri)
meshio.write(f"{d}/meshio_sphere.off", tri)
b = meshio.read(f"{d}/gmsh_box_v41_ascii.msh")
tets = meshio.Mesh(b.points, [("tetra", b.get_cells_type("tetra"))], point_data={"height": b.points[:, 2]})
meshio.write(f"{d}/meshio_box.vtu", tets, binary=False)
PY
echo "meshes regenerated"
