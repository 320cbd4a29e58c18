#pragma once
/// A reference deformation (identify::ReferenceCase) as a file, to be measured elsewhere and identified from, or
/// written from hooke's FEM for another tool.
#include <filesystem>
#include <hooke/identify/reference_case.hpp>
#include <hooke/mesh/mesh.hpp>

namespace hooke::identify {

/// A reference case as a file: a VTU of the rest mesh with point data "displacement" (m, dim components), "force" (N,
/// the applied nodal force; zero at supports) and "fixed" (1 at supports, 0 elsewhere), and under displacement
/// control "prescribed" (1 where an instrument holds the node; its "force" is the measured reaction), or, for a .csv
/// path, the same per node as columns "node,x,y,z,displacement_x,..,force_x,..,fixed[,prescribed]"
/// (io::write_node_csv). Written atomically.
void write_reference(const std::filesystem::path& path, const mesh::Mesh& mesh, const ReferenceCase& reference);
/// Reads a reference written so (or measured: any VTU with those point arrays, or any CSV with those columns, on the
/// same nodes as `mesh`; "fixed" and "prescribed" may be absent, then no node is a support or prescribed). The case is
/// named after the file.
/// @throws IoError, ParseError; InvalidArgument naming the file when the nodes differ from `mesh`'s or an array
///   is missing or has the wrong number of components
ReferenceCase read_reference(const std::filesystem::path& path, const mesh::Mesh& mesh);

}  // namespace hooke::identify
