// Malformed files are rejected with the file and the line (or byte) of the problem.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <hooke/core/error.hpp>
#include <hooke/io/mesh_io.hpp>

namespace hooke::io {
namespace {

namespace fs = std::filesystem;

struct Malformed {
  std::string name, content, expected;  // expected: a substring of the message
  std::int64_t line;                    // expected line (0: byte offset expected instead)
};

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
        Malformed{"truncated.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n",
                  "file ends", 9},
        Malformed{"version.msh", "$MeshFormat\n3.0 0 8\n$EndMeshFormat\n", "not supported", 2},
        Malformed{"bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", "out of range", 6},
        Malformed{"bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "vertex 4", 4},
        Malformed{"bad.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\n",
                  "'vertex'", 6},
        Malformed{"binary_truncated.stl",
                  std::string(80, ' ') + std::string("\x02\x00\x00\x00", 4) + std::string(60, '\0'), "STL", 1},
        Malformed{"bad.node", "3 3 0 0\n1 0 0 0\n2 1 0\n3 0 1 0\n", "out of sequence", 4},
        Malformed{"bad.vtu",
                  "<VTKFile type=\"UnstructuredGrid\">\n<UnstructuredGrid>\n<Piece>\n<Points>\n<DataArray "
                  "format=\"binary\">\n",
                  "only ASCII", 5}),
    [](const auto& param_info) {
      std::string n = param_info.param.name;
      for (char& ch : n)
        if (ch == '.') ch = '_';
      return n;
    });

TEST(MissingFile, IsAnIoError) { EXPECT_THROW(read_mesh("/nonexistent/mesh.msh"), IoError); }
TEST(UnknownExtension, IsAnInvalidArgument) { EXPECT_THROW(read_mesh("mesh.xyz"), InvalidArgument); }

}  // namespace
}  // namespace hooke::io
