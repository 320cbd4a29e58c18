#include <charconv>
#include <cmath>
#include <cstdio>
#include <hooke/core/atomic_file.hpp>
#include <hooke/core/error.hpp>
#include <hooke/io/detail/assemble.hpp>
#include <hooke/io/detail/reader.hpp>
#include <hooke/io/vtu.hpp>
#include <iomanip>
#include <limits>
#include <map>

namespace hooke::io {
namespace {

int vtk_cell_type(mesh::ElementKind kind) {
  switch (kind) {
    case mesh::ElementKind::kQuad: return 9;
    case mesh::ElementKind::kTet: return 10;
    default: return 5;
  }
}

void write_field(std::ostream& out, const Field& f, Eigen::Index count, int dim) {
  if (f.values.size() != count * f.components)
    throw InvalidArgument("field '" + f.name + "' has " + std::to_string(f.values.size()) + " values, expected " +
                          std::to_string(count * f.components));
  const int comps = (f.components == 2 && dim == 2) ? 3 : f.components;
  out << "        <DataArray type=\"Float64\" Name=\"" << f.name << "\" NumberOfComponents=\"" << comps
      << "\" format=\"ascii\">\n";
  for (Eigen::Index i = 0; i < count; ++i) {
    out << "         ";
    for (int c = 0; c < comps; ++c) out << ' ' << (c < f.components ? f.values(f.components * i + c) : 0.0);
    out << '\n';
  }
  out << "        </DataArray>\n";
}

// Attributes of an XML start tag: name="value" pairs.
std::map<std::string, std::string> attributes(const std::string& tag) {
  std::map<std::string, std::string> out;
  size_t p = 0;
  while ((p = tag.find('=', p)) != std::string::npos) {
    size_t k = p;
    while (k > 0 && tag[k - 1] == ' ') --k;
    size_t ks = k;
    while (ks > 0 && tag[ks - 1] != ' ' && tag[ks - 1] != '<') --ks;
    size_t q1 = tag.find_first_of("\"'", p);
    if (q1 == std::string::npos) break;
    size_t q2 = tag.find(tag[q1], q1 + 1);
    if (q2 == std::string::npos) break;
    out[tag.substr(ks, k - ks)] = tag.substr(q1 + 1, q2 - q1 - 1);
    p = q2 + 1;
  }
  return out;
}

// `value` from the file as a whole number in [lo, hi]; a ParseError naming `what` otherwise (casting an out-of-range
// double to an integer is undefined behaviour).
// The error names the line of the array's <DataArray> tag (`at`).
double whole_number(const detail::Reader& r, size_t at, double value, double lo, double hi, const std::string& what) {
  if (!(value >= lo && value <= hi) || value != std::floor(value)) {
    char text[160];
    std::snprintf(text, sizeof text, " is %.17g, not a whole number in [%.17g, %.17g]", value, lo, hi);
    r.fail_at_offset(at, what + text);
  }
  return value;
}

}  // namespace

namespace {

// One piece of `cells` (#C x nodes per cell, all of VTK type `cell_type`) on `nodes` (#V x dim), with the cell
// fields after `region` (when given).
void write_grid(std::ostream& out, const RowMatX& nodes, const RowMatXi& cells, int cell_type,
                const std::vector<Field>& point_data, const std::vector<Field>& cell_data, const Field* region) {
  const auto nv = nodes.rows(), ne = cells.rows(), npc = cells.cols();
  const int dim = static_cast<int>(nodes.cols());
  out << std::setprecision(17);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      << "  <UnstructuredGrid>\n"
      << "    <Piece NumberOfPoints=\"" << nv << "\" NumberOfCells=\"" << ne << "\">\n"
      << "      <PointData>\n";
  for (const Field& f : point_data) write_field(out, f, nv, dim);
  out << "      </PointData>\n      <CellData>\n";
  if (region) write_field(out, *region, ne, dim);
  for (const Field& f : cell_data) write_field(out, f, ne, dim);
  out << "      </CellData>\n      <Points>\n"
      << "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (Eigen::Index i = 0; i < nv; ++i)
    out << "          " << nodes(i, 0) << ' ' << nodes(i, 1) << ' ' << (dim == 3 ? nodes(i, 2) : 0.0) << '\n';
  out << "        </DataArray>\n      </Points>\n      <Cells>\n"
      << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (Eigen::Index e = 0; e < ne; ++e) {
    out << "         ";
    for (Eigen::Index k = 0; k < npc; ++k) out << ' ' << cells(e, k);
    out << '\n';
  }
  out << "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (Eigen::Index e = 0; e < ne; ++e) out << "          " << npc * (e + 1) << '\n';
  out << "        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (Eigen::Index e = 0; e < ne; ++e) out << "          " << cell_type << '\n';
  out << "        </DataArray>\n      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
}

}  // namespace

void write_vtu(const std::filesystem::path& path, const mesh::Mesh& m, const std::vector<Field>& point_data,
               const std::vector<Field>& cell_data) {
  const int ne = m.element_count();
  const Field region{"region", 1, m.region.size() == ne ? m.region.cast<double>().eval() : VecX::Zero(ne)};
  require_finite_positions(m.nodes, path);
  for (const auto* fields : {&point_data, &cell_data})
    for (const Field& f : *fields) require_finite(f, path);
  write_file_atomically(path, [&](std::ostream& out) {
    write_grid(out, m.nodes, m.elements, vtk_cell_type(m.kind), point_data, cell_data, &region);
  });
}

void write_vtu_lines(const std::filesystem::path& path, const RowMatX& nodes,
                     const std::vector<std::array<int, 2>>& lines, const std::vector<Field>& point_data,
                     const std::vector<Field>& cell_data) {
  RowMatXi cells(static_cast<Eigen::Index>(lines.size()), 2);
  for (size_t k = 0; k < lines.size(); ++k) {
    for (int a = 0; a < 2; ++a)
      if (lines[k][static_cast<size_t>(a)] < 0 || lines[k][static_cast<size_t>(a)] >= nodes.rows())
        throw InvalidArgument("line " + std::to_string(k) + " names a node out of range");
    cells(static_cast<Eigen::Index>(k), 0) = lines[k][0];
    cells(static_cast<Eigen::Index>(k), 1) = lines[k][1];
  }
  require_finite_positions(nodes, path);
  for (const auto* fields : {&point_data, &cell_data})
    for (const Field& f : *fields) require_finite(f, path);
  write_file_atomically(path, [&](std::ostream& out) {
    write_grid(out, nodes, cells, 3, point_data, cell_data, nullptr);  // VTK_LINE = 3
  });
}

VtuContents read_vtu(const std::filesystem::path& path) {
  detail::Reader r = detail::Reader::open(path);
  const std::string& s = r.data();
  if (s.find("<VTKFile") == std::string::npos || s.find("UnstructuredGrid") == std::string::npos)
    r.fail("not a VTK XML unstructured grid (no <VTKFile type=\"UnstructuredGrid\">)");
  if (s.find("<AppendedData") != std::string::npos) r.fail("appended binary data is not supported; write ASCII VTU");
  if (s.find("<Piece", s.find("<Piece") + 1) != std::string::npos) r.fail("multi-piece VTU files are not supported");

  struct Array {
    std::string name, section;
    size_t at = 0;  // where its <DataArray> tag starts
    int components = 1;
    std::vector<double> values;
  };
  std::vector<Array> arrays;
  std::string section;
  size_t pos = 0;
  while ((pos = s.find('<', pos)) != std::string::npos) {
    const size_t close = s.find('>', pos);
    if (close == std::string::npos) break;
    const std::string tag = s.substr(pos, close - pos + 1);
    for (const char* sec : {"PointData", "CellData", "Points", "Cells"}) {
      if (tag.rfind(std::string("<") + sec, 0) == 0 &&
          (tag[std::string(sec).size() + 1] == '>' || tag[std::string(sec).size() + 1] == ' '))
        section = sec;
    }
    if (tag.rfind("<DataArray", 0) == 0) {
      auto attr = attributes(tag);
      if (attr.count("format") && attr["format"] != "ascii") {
        r.fail_at_offset(pos, "DataArray '" + attr["Name"] + "' has format=\"" + attr["format"] +
                                  "\"; only ASCII VTU is read (write it with hooke or choose ASCII in ParaView)");
      }
      const size_t end = s.find("</DataArray>", close);
      if (end == std::string::npos) {
        r.fail_at_offset(pos, "DataArray without </DataArray>");
      }
      Array a;
      a.name = attr.count("Name") ? attr["Name"] : "";
      a.section = section;
      a.at = pos;
      a.components = 1;
      if (attr.count("NumberOfComponents")) {
        const std::string& c = attr["NumberOfComponents"];
        const auto [parsed, ec] = std::from_chars(c.data(), c.data() + c.size(), a.components);
        if (ec != std::errc() || parsed != c.data() + c.size() || a.components < 1 || a.components > 9)
          r.fail_at_offset(pos, "DataArray '" + a.name + "' has NumberOfComponents=\"" + c + "\" (1 to 9 expected)");
      }
      r.window(close + 1, end);  // the array's text, read in place (a copy per array was quadratic)
      while (true) {
        r.skip_space();
        if (r.at_end()) break;
        a.values.push_back(r.number("a data value"));
      }
      r.window(end, s.size());
      arrays.push_back(std::move(a));
      pos = end;
    } else {
      pos = close;
    }
  }
  const Array *points = nullptr, *conn = nullptr, *offsets = nullptr, *types = nullptr;
  for (const Array& a : arrays) {
    if (a.section == "Points") points = &a;
    if (a.section == "Cells" && a.name == "connectivity") conn = &a;
    if (a.section == "Cells" && a.name == "offsets") offsets = &a;
    if (a.section == "Cells" && a.name == "types") types = &a;
  }
  if (!points || !conn || !offsets || !types) r.fail("VTU file lacks Points or Cells arrays");
  if (points->values.size() % 3 != 0) r.fail("Points array size is not a multiple of 3");
  const Eigen::Index nv = static_cast<Eigen::Index>(points->values.size() / 3);
  RowMatX nodes(nv, 3);
  for (Eigen::Index i = 0; i < nodes.size(); ++i) nodes.data()[i] = points->values[static_cast<size_t>(i)];
  detail::RawElements raw;
  size_t start = 0;
  if (offsets->values.size() != types->values.size()) r.fail("offsets and types differ in length");
  std::vector<int> v;
  for (size_t c = 0; c < types->values.size(); ++c) {
    const std::string cell = "cell " + std::to_string(c);
    const auto stop = static_cast<size_t>(whole_number(
        r, offsets->at, offsets->values[c], static_cast<double>(start), static_cast<double>(conn->values.size()),
        cell + "'s offset (at least the previous offset, at most the connectivity's length)"));
    const int type = static_cast<int>(whole_number(r, types->at, types->values[c], 0.0, 255.0, cell + "'s VTK type"));
    v.clear();
    for (size_t k = start; k < stop; ++k)
      v.push_back(static_cast<int>(
          whole_number(r, conn->at, conn->values[k], 0.0, static_cast<double>(nv) - 1.0, cell + "'s node index")));
    start = stop;
    const mesh::ElementOrigin o{static_cast<std::int64_t>(c), 0};  // the cell id ParaView shows
    if (type == 5 && v.size() == 3) {
      raw.add_triangle({v[0], v[1], v[2]}, 0, o);
    } else if (type == 9 && v.size() == 4) {
      raw.add_quad({v[0], v[1], v[2], v[3]}, 0, o);
    } else if (type == 10 && v.size() == 4) {
      raw.add_tet({v[0], v[1], v[2], v[3]}, 0, o);
    } else if (type != 1 && type != 3) {  // vertices and lines are skipped
      r.fail("cell " + std::to_string(c) + " has VTK type " + std::to_string(type) +
             " (hooke reads triangles 5, quads 9 and tets 10)");
    }
  }
  VtuContents out;
  out.mesh = detail::assemble(r.name(), nodes, std::move(raw));
  const Eigen::Index ne = out.mesh.element_count();
  for (const Array& a : arrays) {
    if (a.section != "PointData" && a.section != "CellData") continue;
    Field f{a.name, a.components, Eigen::Map<const VecX>(a.values.data(), static_cast<Eigen::Index>(a.values.size()))};
    if (a.section == "CellData" && a.name == "region" && f.values.size() == ne) {
      out.mesh.region.resize(ne);
      for (Eigen::Index e = 0; e < ne; ++e)
        out.mesh.region(e) = static_cast<int>(whole_number(r, a.at, f.values(e), std::numeric_limits<int>::min(),
                                                           std::numeric_limits<int>::max(), "a region tag"));
      continue;
    }
    (a.section == "PointData" ? out.point_data : out.cell_data).push_back(std::move(f));
  }
  return out;
}

}  // namespace hooke::io
