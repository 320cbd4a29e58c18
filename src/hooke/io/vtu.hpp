#pragma once
/// VTK XML unstructured grids (.vtu): written with point and cell data, read back (ASCII data arrays).
#include <array>
#include <filesystem>
#include <hooke/io/field.hpp>
#include <hooke/mesh/mesh.hpp>
#include <vector>

namespace hooke::io {

/// Writes `mesh` with point and cell fields as ASCII VTU (full double precision), atomically.
/// 2D meshes get z = 0 and 2-component fields are padded to 3 so that ParaView draws them as vectors.
/// The element region is always written as the cell field "region".
/// @throws InvalidArgument if a field's size does not match #V or #E times its components
void write_vtu(const std::filesystem::path& path, const mesh::Mesh& mesh, const std::vector<Field>& point_data = {},
               const std::vector<Field>& cell_data = {});

/// Writes line cells (VTK type 3) between `nodes` (#V x 2 or 3, m) as ASCII VTU, atomically: springs coloured
/// by a cell field in ParaView. Fields as in write_vtu (no "region").
/// @throws InvalidArgument on a node index out of range or a field of the wrong size
void write_vtu_lines(const std::filesystem::path& path, const RowMatX& nodes,
                     const std::vector<std::array<int, 2>>& lines, const std::vector<Field>& point_data = {},
                     const std::vector<Field>& cell_data = {});

/// Contents of a VTU file.
struct VtuContents {
  mesh::Mesh mesh;
  std::vector<Field> point_data;
  std::vector<Field> cell_data;
};

/// Reads a VTU file with format="ascii" data arrays holding one cell type (triangle 5, quad 9, tet 10).
/// A grid whose points all have z = 0 becomes a planar mesh. Binary and appended data are rejected with a
/// clear message. Cell field "region" becomes mesh.region.
/// @throws IoError, ParseError{file, line}
VtuContents read_vtu(const std::filesystem::path& path);

}  // namespace hooke::io
