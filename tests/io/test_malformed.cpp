// Malformed files are rejected with the file and the line (or byte) of the problem.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <hooke/core/error.hpp>
#include <hooke/io/mesh_io.hpp>
#include <utility>
#include <vector>

namespace hooke::io {
namespace {

namespace fs = std::filesystem;

struct Malformed {
  std::string name, content, expected;  // expected: a substring of the message
  std::int64_t line;                    // expected line (0: byte offset expected instead)
};

// A VTU file with four nodes of a unit tet and one cell given by its connectivity, offsets and types arrays.
std::string vtu_with_cells(const std::string& connectivity, const std::string& offsets, const std::string& types) {
  return "<VTKFile type=\"UnstructuredGrid\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">\n"
         "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n"
         "0 0 0 1 0 0 0 1 0 0 0 1\n</DataArray>\n</Points>\n<Cells>\n"
         "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n" +
         connectivity + "\n</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n" + offsets +
         "\n</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n" + types +
         "\n</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

class MalformedFile : public ::testing::TestWithParam<Malformed> {};

TEST_P(MalformedFile, IsRejectedWithLocation) {
  const fs::path dir = fs::temp_directory_path() / "hooke_malformed";
  fs::create_directories(dir);
  const fs::path path = dir / GetParam().name;
  {
    std::ofstream out(path, std::ios::binary);
    out << GetParam().content;
  }
  try {
    read_mesh(path);
    FAIL() << "accepted " << GetParam().name;
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), path.string());
    if (GetParam().line > 0) {
      EXPECT_EQ(e.line(), GetParam().line) << e.what();
    } else {
      EXPECT_GE(e.byte_offset(), 0) << e.what();
    }
    EXPECT_NE(std::string(e.what()).find(GetParam().expected), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Formats, MalformedFile,
    ::testing::Values(
        Malformed{"bad_number.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 0 0 0\n2 0 x 0\n$EndNodes\n",
                  "'x'", 7},
        Malformed{"bad_node_ref.msh",
                  "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 "
                  "0\n$EndNodes\n$Elements\n1\n1 2 2 0 1 1 2 9\n$EndElements\n",
                  "node 9", 12},
        // Truncated: the declared 3 nodes cannot fit in the 5 bytes left (reported where the count is read).
        Malformed{"truncated.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n",
                  "truncated", 6},
        Malformed{"truncated_coordinates.msh",
                  "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 1 1 1\n2 1 0 1\n1\n0 0\n          \n", "file ends",
                  10},
        Malformed{"version.msh", "$MeshFormat\n3.0 0 8\n$EndMeshFormat\n", "not supported", 2},
        Malformed{"bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", "out of range", 6},
        Malformed{"bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "vertex 4", 4},
        Malformed{"bad.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\n",
                  "'vertex'", 6},
        Malformed{"binary_truncated.stl",
                  std::string(80, ' ') + std::string("\x02\x00\x00\x00", 4) + std::string(60, '\0'), "STL", 1},
        Malformed{"bad.node", "3 3 0 0\n1 0 0 0\n2 1 0\n3 0 1 0\n# long enough for 3 points\n", "out of sequence", 4},
        Malformed{"bad.vtu",
                  "<VTKFile type=\"UnstructuredGrid\">\n<UnstructuredGrid>\n<Piece>\n<Points>\n<DataArray "
                  "format=\"binary\">\n",
                  "only ASCII", 5},
        // Issue 16 item 1: a parametric node block with an entity dimension from the file used to overflow a
        // 6-double buffer.
        Malformed{"parametric_dim.msh",
                  "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 1 1 1\n9 1 1 1\n1\n0 0 0 0 0 0 0 0 0 0 0 0\n",
                  "entity dimension is 9", 6},
        // Item 3: a declared block of 10^9 nodes in a 90-byte file used to allocate 7.6 GB before failing.
        Malformed{"huge_block.msh",
                  "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 1000000000 1 1000000000\n2 1 0 1000000000\n1\n",
                  "cannot fit", 6},
        // Item 4: the version token went through std::stod (an internal error, exit 4).
        Malformed{"version_token.msh", "$MeshFormat\nfour 0 8\n$EndMeshFormat\n", "version number", 2},
        Malformed{"components.vtu",
                  "<VTKFile type=\"UnstructuredGrid\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"1\" "
                  "NumberOfCells=\"0\">\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"x\" "
                  "format=\"ascii\">\n0 0 0\n</DataArray>\n</Points>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n",
                  "NumberOfComponents", 5},
        // Item 3 for OFF and TetGen: the counts used to size the arrays before any data was read (bad_alloc, exit 4).
        Malformed{"huge.off", "OFF\n1000000000 1 0\n0 0 0\n", "the vertex count 1000000000 cannot fit", 2},
        Malformed{"huge_faces.off", "OFF\n3 1000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "the face count", 2},
        Malformed{"huge.node", "1000000000 3 0 0\n1 0 0 0\n", "the number of points 1000000000 cannot fit", 1},
        // Item 4 for VTU: file doubles were cast to size_t and int unchecked (undefined behaviour).
        Malformed{"huge_offset.vtu", vtu_with_cells("0 1 2 3", "1e300", "10"), "cell 0's offset", 13},
        Malformed{"negative_type.vtu", vtu_with_cells("0 1 2 3", "4", "-1"), "cell 0's VTK type", 16},
        Malformed{"fractional_node.vtu", vtu_with_cells("0 1 2.5 3", "4", "10"), "cell 0's node index", 10},
        Malformed{"node_out_of_range.vtu", vtu_with_cells("0 1 2 1e12", "4", "10"), "cell 0's node index", 10}),
    [](const auto& param_info) {
      std::string n = param_info.param.name;
      for (char& ch : n)
        if (ch == '.') ch = '_';
      return n;
    });

// Issue 16 item 2: in a binary $Entities section a boundary count of 2^62 made the skip of 4 x count bytes wrap
// around the bounds check, and the reader looped forever. Now the count is checked against the bytes left.
TEST(MalformedBinaryMsh, HugeBoundaryCountIsRejectedNotLoopedOn) {
  auto u64 = [](std::uint64_t v) { return std::string(reinterpret_cast<const char*>(&v), 8); };
  auto i32 = [](std::int32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  std::string content = "$MeshFormat\n4.1 1 8\n" + i32(1) + "\n$EndMeshFormat\n$Entities\n";
  content += u64(0) + u64(1) + u64(0) + u64(0);               // one curve
  content += i32(1) + std::string(6 * sizeof(double), '\0');  // its tag and bounding box
  content += u64(0) + u64(std::uint64_t(1) << 62);            // no physical tags, 2^62 boundary tags
  content += std::string(16, '\0') + "\n$EndEntities\n";
  const fs::path path = fs::temp_directory_path() / "hooke_malformed" / "huge_bound.msh";
  fs::create_directories(path.parent_path());
  {
    std::ofstream out(path, std::ios::binary);
    out << content;
  }
  try {
    read_mesh(path);
    FAIL() << "accepted";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot fit"), std::string::npos) << e.what();
  }
}

// Writes `files` (name, content) into a fresh folder and returns it.
fs::path write_files(const std::string& folder, const std::vector<std::pair<std::string, std::string>>& files) {
  const fs::path dir = fs::temp_directory_path() / "hooke_malformed" / folder;
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (const auto& [name, content] : files) std::ofstream(dir / name, std::ios::binary) << content;
  return dir;
}

const char* kUnitTetNodes = "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";

TEST(MalformedTetGen, HugeTetCountIsRefusedBeforeReading) {
  const fs::path dir =
      write_files("tetgen_count", {{"m.node", kUnitTetNodes}, {"m.ele", "1000000000 4 0\n1 1 2 3 4\n"}});
  try {
    read_mesh(dir / "m.ele");
    FAIL() << "accepted";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("the number of tetrahedra 1000000000 cannot fit"), std::string::npos)
        << e.what();
  }
}

TEST(MalformedTetGen, RegionAttributeOutOfIntRangeIsAParseError) {
  const fs::path dir = write_files("tetgen_region", {{"m.node", kUnitTetNodes}, {"m.ele", "1 4 1\n1 1 2 3 4 1e20\n"}});
  try {
    read_mesh(dir / "m.ele");
    FAIL() << "accepted";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 2) << e.what();
    EXPECT_NE(std::string(e.what()).find("not a whole number"), std::string::npos) << e.what();
  }
}

// Item 6: "MESH.FACE" was read as a tet file (the extension was compared in lower case only).
TEST(TetGenFiles, UpperCaseExtensionsAreTheSameKinds) {
  const fs::path dir = write_files("tetgen_upper", {{"M.NODE", kUnitTetNodes}, {"M.FACE", "1 0\n1 1 2 3\n"}});
  const mesh::Mesh m = read_mesh(dir / "M.FACE");
  EXPECT_EQ(m.kind, mesh::ElementKind::kSurfaceTriangle);  // node 4 is off the plane
  EXPECT_EQ(m.element_count(), 1);
}

// Item 6: elements were named by their 0-based index among the kept elements ("tet 1"), not as the file names them.
TEST(ElementLabels, NameTheFilesElementNumberAndLine) {
  // Element 7 (a line) is skipped; the degenerate tet is Gmsh element 60 on line 16 and hooke's tet 1.
  const std::string msh =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 0\n"
      "$EndNodes\n$Elements\n3\n7 1 0 1 2\n12 4 0 1 2 3 4\n60 4 0 1 2 3 5\n$EndElements\n";
  const fs::path dir = write_files("labels", {{"m.msh", msh}});
  try {
    read_mesh(dir / "m.msh");
    FAIL() << "accepted a flat tet";
  } catch (const InvalidMesh& e) {
    EXPECT_NE(std::string(e.what()).find("tet 1 (element 60, line 16 of "), std::string::npos) << e.what();
  }
}

TEST(MissingFile, IsAnIoError) { EXPECT_THROW(read_mesh("/nonexistent/mesh.msh"), IoError); }
TEST(UnknownExtension, IsAnInvalidArgument) { EXPECT_THROW(read_mesh("mesh.xyz"), InvalidArgument); }

}  // namespace
}  // namespace hooke::io
