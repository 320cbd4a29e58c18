#pragma once
/// The volume meshers behind mesh::tetrahedralize, by name: Netgen in process, or TetGen's `tetgen` program run on
/// files in a temporary folder (TetGen is AGPL-3, so hooke never links it; docs/meshing.md).
#include <hooke/mesh/tetrahedralize.hpp>

namespace hooke::io {

/// The mesher `mesher` names. For kTetgen: runs `tetgen -pYq<ratio>/<angle>a<volume>` (found on PATH) on an OFF
/// copy of the surface, the volume bound being the regular tet of edge options.max_size, and reads its .node/.ele
/// back; the input nodes come back first and unmoved (-Y: no Steiner points on the surface).
/// @throws InvalidArgument when tetgen is not installed (naming `scripts/setup.sh`), InvalidMesh with the
///   end of TetGen's own output when it fails, IoError when the temporary folder cannot be written
mesh::VolumeMesher volume_mesher(mesh::Mesher mesher);

/// mesh::tetrahedralize with the mesher options.mesher names (the one call for front ends: CLI, Python, model
/// factory). Units, preconditions, report and errors as mesh::tetrahedralize and volume_mesher.
mesh::Mesh tetrahedralize(mesh::Mesh surface, const mesh::TetrahedralizeOptions& options = {},
                          mesh::TetrahedralizeReport* report = nullptr);

}  // namespace hooke::io
