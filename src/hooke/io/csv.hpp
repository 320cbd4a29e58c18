#pragma once
/// Per-node tables as CSV (one row per node), for spreadsheets and plotting scripts.
#include <filesystem>
#include <hooke/io/field.hpp>
#include <hooke/mesh/mesh.hpp>
#include <string>
#include <vector>

namespace hooke::io {

/// Writes "node,x,y[,z],<field>_<c>..." with one row per node: rest coordinates (m) and point fields.
/// @throws InvalidArgument if a field does not have #V x components values
void write_node_csv(const std::filesystem::path& path, const mesh::Mesh& mesh, const std::vector<Field>& fields);

/// A CSV table of numbers with a header line: column names and one row of values per line.
struct CsvTable {
  std::vector<std::string> columns;  ///< header names, trimmed
  RowMatX values;                    ///< #rows x #columns
  /// Index of the column `name`, or -1.
  int column(const std::string& name) const;
};

/// Reads a comma-separated table: a header line of names, then rows of as many finite numbers (blank lines and lines
/// starting with '#' skipped), as write_node_csv writes.
/// @throws IoError when the file cannot be read; ParseError naming the file and line for a row of another length, a
///   token that is not a finite number, or a file without a header or rows
CsvTable read_csv_table(const std::filesystem::path& path);

}  // namespace hooke::io
