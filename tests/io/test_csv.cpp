// CSV tables: what write_node_csv writes reads back; malformed rows are ParseErrors naming the file and line.
#include <gtest/gtest.h>
#include <filesystem>
#include <fstream>
#include <hooke/core/error.hpp>
#include <hooke/io/csv.hpp>
#include <hooke/mesh/generators.hpp>

using namespace hooke;

namespace {
std::filesystem::path write_text(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path;
}
}  // namespace

TEST(CsvTable, ReadsWhatWriteNodeCsvWrites) {
  const mesh::Mesh m = mesh::tet_box(0.01, 0.02, 0.03, 1, 1, 1);
  io::Field f{"u", 3, VecX::LinSpaced(3 * m.node_count(), -1.0, 1.0)};
  const auto path = std::filesystem::temp_directory_path() / "hooke_csv_table.csv";
  io::write_node_csv(path, m, {f});
  const io::CsvTable t = io::read_csv_table(path);
  ASSERT_EQ(t.values.rows(), m.node_count());
  EXPECT_EQ(t.columns, (std::vector<std::string>{"node", "x", "y", "z", "u_x", "u_y", "u_z"}));
  EXPECT_EQ(t.column("u_y"), 5);
  EXPECT_EQ(t.column("v"), -1);
  for (int i = 0; i < m.node_count(); ++i) {
    EXPECT_EQ(t.values(i, 0), i);
    EXPECT_NEAR(t.values(i, 3), m.nodes(i, 2), 1e-12);
    EXPECT_NEAR(t.values(i, 5), f.values(3 * i + 1), 1e-11);
  }
  std::filesystem::remove(path);
}

TEST(CsvTable, MalformedRowsNameTheLine) {
  const auto expect_line = [](const std::string& text, std::int64_t line, const std::string& words) {
    const auto path = write_text("hooke_bad.csv", text);
    try {
      io::read_csv_table(path);
      FAIL() << "read: " << text;
    } catch (const ParseError& e) {
      EXPECT_EQ(e.line(), line) << e.what();
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  expect_line("a,b\n1,2\n3\n", 3, "1 values where the header has 2 columns");
  expect_line("a,b\n# comment\n1,x\n", 3, "column 'b': 'x' is not a finite number");
  expect_line("a,b\n1,nan\n", 2, "not a finite number");
  expect_line("a,b\n1,1e999\n", 2, "not a finite number");
  expect_line("a,b\n1,\n", 2, "column 'b': ''");
  expect_line("a,b\n", 1, "no header line and rows");
  EXPECT_THROW(io::read_csv_table("/nonexistent/x.csv"), IoError);
}
