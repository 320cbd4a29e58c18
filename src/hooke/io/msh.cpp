#include <charconv>
#include <cstdint>
#include <hooke/core/atomic_file.hpp>
#include <hooke/io/detail/assemble.hpp>
#include <hooke/io/detail/reader.hpp>
#include <hooke/io/msh.hpp>
#include <iomanip>
#include <map>
#include <unordered_map>

namespace hooke::io {
namespace {

using detail::Reader;

// Nodes per element of the Gmsh element types hooke reads or has to skip; -1 where unsupported.
int gmsh_type_nodes(std::int64_t type) {
  switch (type) {
    case 15: return 1;  // point
    case 1: return 2;   // 2-node line
    case 2: return 3;   // 3-node triangle
    case 3: return 4;   // 4-node quadrangle
    case 4: return 4;   // 4-node tetrahedron
    case 8: return 3;   // 3-node line (skipped: only in higher-order meshes)
    default: return -1;
  }
}

struct MshParser {
  explicit MshParser(Reader& reader) : r(reader) {}
  Reader& r;
  bool binary = false;
  double version = 0.0;
  std::vector<double> xyz;                             // 3 per node
  std::unordered_map<std::int64_t, int> node_index;    // file tag -> 0-based index
  std::map<std::pair<int, int>, int> entity_physical;  // (dim, tag) -> first physical tag (4.1)
  detail::RawElements raw;

  void expect_end(const std::string& section) {
    const std::string end = "$End" + section;
    if (r.expect_token(end.c_str()) != end) r.fail("expected " + end);
  }

  int node(std::int64_t tag) {
    const auto it = node_index.find(tag);
    if (it == node_index.end()) r.fail("element refers to node " + std::to_string(tag) + ", which is not defined");
    return it->second;
  }

  void add_node(std::int64_t tag, double x, double y, double z) {
    if (!node_index.emplace(tag, static_cast<int>(xyz.size() / 3)).second)
      r.fail("node " + std::to_string(tag) + " is defined twice");
    xyz.insert(xyz.end(), {x, y, z});
  }

  // Keeps triangles, quads and tets (other types are skipped); `number` is the file's element tag.
  void add_element(std::int64_t type, const std::int64_t* tags, int region, std::int64_t number) {
    const mesh::ElementOrigin o{number, binary ? 0 : r.line()};
    if (type == 2)
      raw.add_triangle({node(tags[0]), node(tags[1]), node(tags[2])}, region, o);
    else if (type == 3)
      raw.add_quad({node(tags[0]), node(tags[1]), node(tags[2]), node(tags[3])}, region, o);
    else if (type == 4)
      raw.add_tet({node(tags[0]), node(tags[1]), node(tags[2]), node(tags[3])}, region, o);
  }

  int type_nodes(std::int64_t type) {
    const int n = gmsh_type_nodes(type);
    if (n < 0)
      r.fail("element type " + std::to_string(type) +
             " is not supported (hooke reads linear points, lines, triangles, quadrangles and tetrahedra)");
    return n;
  }

  void mesh_format() {
    const std::string_view v = r.expect_token("the version number");
    const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), version);
    if (ec != std::errc() || end != v.data() + v.size())
      r.fail("expected the MSH version number (e.g. 4.1), found '" + std::string(v) + "'");
    const std::int64_t file_type = r.integer("the file type");
    const std::int64_t data_size = r.integer("the data size");
    if (version != 2.2 && !(version >= 4.1 && version < 4.2))
      r.fail("MSH version " + std::string(v) + " is not supported (use 2.2 or 4.1)");
    if (data_size != 8) r.fail("data size " + std::to_string(data_size) + " is not supported (8 expected)");
    binary = file_type == 1;
    if (binary) {
      r.skip_line();
      if (r.binary<int>("the endianness marker") != 1)
        r.fail_at_byte("binary MSH written with another byte order is not supported");
    }
    expect_end("MeshFormat");
  }

  void nodes_v22() {
    const std::int64_t n = r.integer("the number of nodes");
    if (n < 0) r.fail("negative node count");
    if (binary) {
      r.skip_line();
      for (std::int64_t i = 0; i < n; ++i) {
        const int tag = r.binary<int>("a node tag");
        const double x = r.binary<double>("node coordinates"), y = r.binary<double>("node coordinates"),
                     z = r.binary<double>("node coordinates");
        add_node(tag, x, y, z);
      }
    } else {
      for (std::int64_t i = 0; i < n; ++i) {
        const std::int64_t tag = r.integer("a node tag");
        const double x = r.number("x"), y = r.number("y"), z = r.number("z");
        add_node(tag, x, y, z);
      }
    }
    expect_end("Nodes");
  }

  void elements_v22() {
    const std::int64_t n = r.integer("the number of elements");
    std::int64_t tags[16];
    if (binary) {
      r.skip_line();
      std::int64_t done = 0;
      while (done < n) {
        const int type = r.binary<int>("an element block header");
        const int count = r.binary<int>("an element block header");
        const int ntags = r.binary<int>("an element block header");
        if (count <= 0 || ntags < 0) r.fail_at_byte("invalid element block header");
        const int nn = type_nodes(type);
        for (int e = 0; e < count; ++e) {
          const int number = r.binary<int>("an element tag");
          int region = 0;
          for (int t = 0; t < ntags; ++t) {
            const int v = r.binary<int>("element tags");
            if (t == 0) region = v;
          }
          for (int k = 0; k < nn; ++k) tags[k] = r.binary<int>("element nodes");
          add_element(type, tags, region, number);
        }
        done += count;
      }
    } else {
      for (std::int64_t e = 0; e < n; ++e) {
        const std::int64_t number = r.integer("an element tag");
        const std::int64_t type = r.integer("an element type");
        const std::int64_t ntags = r.integer("the number of element tags");
        if (ntags < 0 || ntags > 64) r.fail("invalid number of element tags");
        int region = 0;
        for (std::int64_t t = 0; t < ntags; ++t) {
          const std::int64_t v = r.integer("an element tag");
          if (t == 0) region = static_cast<int>(v);
        }
        const int nn = type_nodes(type);
        for (int k = 0; k < nn; ++k) tags[k] = r.integer("an element node");
        add_element(type, tags, region, number);
      }
    }
    expect_end("Elements");
  }

  // $Entities (4.1): physical tags of each entity.
  void entities_v41() {
    if (binary) r.skip_line();  // binary data starts after the section header's newline
    std::uint64_t count[4];
    for (auto& c : count)
      c = binary ? r.binary<std::uint64_t>("entity counts") : static_cast<std::uint64_t>(r.integer("an entity count"));
    if (binary) {
      for (int dim = 0; dim < 4; ++dim)
        for (std::uint64_t i = 0; i < count[dim]; ++i) {
          const int tag = r.binary<int>("an entity tag");
          r.skip_bytes(sizeof(double) * (dim == 0 ? 3 : 6), "an entity bounding box");
          const auto nphys = r.binary<std::uint64_t>("an entity's physical tag count");
          int first = 0;
          for (std::uint64_t p = 0; p < nphys; ++p) {
            const int v = r.binary<int>("a physical tag");
            if (p == 0) first = v;
          }
          entity_physical[{dim, tag}] = first;
          if (dim > 0) {
            const auto nbound = r.binary<std::uint64_t>("an entity's boundary count");
            r.skip_bytes(sizeof(int) * r.bounded_count(nbound, sizeof(int), "the entity boundary count"),
                         "entity boundary tags");
          }
        }
    } else {
      for (int dim = 0; dim < 4; ++dim)
        for (std::uint64_t i = 0; i < count[dim]; ++i) {
          const int tag = static_cast<int>(r.integer("an entity tag"));
          for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) r.number("an entity bounding box");
          const std::int64_t nphys = r.integer("an entity's physical tag count");
          int first = 0;
          for (std::int64_t p = 0; p < nphys; ++p) {
            const std::int64_t v = r.integer("a physical tag");
            if (p == 0) first = static_cast<int>(v);
          }
          entity_physical[{dim, tag}] = first;
          if (dim > 0) {
            const std::int64_t nbound = r.integer("an entity's boundary count");
            for (std::int64_t b = 0; b < nbound; ++b) r.integer("a boundary tag");
          }
        }
    }
    expect_end("Entities");
  }

  std::uint64_t size_value(const char* what) {
    if (binary) return r.binary<std::uint64_t>(what);
    const std::int64_t v = r.integer(what);
    if (v < 0) r.fail(std::string("negative ") + what);
    return static_cast<std::uint64_t>(v);
  }
  int int_value(const char* what) { return binary ? r.binary<int>(what) : static_cast<int>(r.integer(what)); }

  void nodes_v41() {
    if (binary) r.skip_line();
    const std::uint64_t blocks = size_value("the number of node blocks");
    size_value("the number of nodes");
    size_value("the minimum node tag");
    size_value("the maximum node tag");
    for (std::uint64_t b = 0; b < blocks; ++b) {
      const int dim = int_value("a node block's entity dimension");
      if (dim < 0 || dim > 3) r.fail("a node block's entity dimension is " + std::to_string(dim) + " (0 to 3)");
      int_value("a node block's entity tag");
      const int parametric = int_value("the parametric flag");
      if (parametric != 0 && parametric != 1)
        r.fail("the parametric flag is " + std::to_string(parametric) + " (0 or 1)");
      // Each node takes a tag and three coordinates: at least 32 bytes binary, 8 as text ("1\n0 0 0\n").
      const std::uint64_t n =
          r.bounded_count(size_value("a node block's size"), binary ? 32 : 8, "the node block size");
      std::vector<std::int64_t> tags(n);
      for (auto& t : tags) t = static_cast<std::int64_t>(size_value("a node tag"));
      const int per_node = 3 + (parametric ? dim : 0);
      for (std::uint64_t i = 0; i < n; ++i) {
        double c[6] = {0, 0, 0, 0, 0, 0};
        for (int k = 0; k < per_node; ++k)
          c[k] = binary ? r.binary<double>("node coordinates") : r.number("a coordinate");
        add_node(tags[i], c[0], c[1], c[2]);
      }
    }
    expect_end("Nodes");
  }

  void elements_v41() {
    if (binary) r.skip_line();
    const std::uint64_t blocks = size_value("the number of element blocks");
    size_value("the number of elements");
    size_value("the minimum element tag");
    size_value("the maximum element tag");
    std::int64_t tags[16];
    for (std::uint64_t b = 0; b < blocks; ++b) {
      const int dim = int_value("an element block's entity dimension");
      const int entity = int_value("an element block's entity tag");
      const int type = int_value("an element type");
      const std::uint64_t n = size_value("an element block's size");
      const int nn = type_nodes(type);
      const auto it = entity_physical.find({dim, entity});
      const int region = it == entity_physical.end() ? 0 : it->second;
      for (std::uint64_t e = 0; e < n; ++e) {
        const auto number = static_cast<std::int64_t>(size_value("an element tag"));
        for (int k = 0; k < nn; ++k) tags[k] = static_cast<std::int64_t>(size_value("an element node"));
        add_element(type, tags, region, number);
      }
    }
    expect_end("Elements");
  }

  void skip_section(std::string_view name) {
    const std::string end = "$End" + std::string(name.substr(1));
    const size_t at = r.data().find(end, r.offset());
    if (at == std::string::npos) r.fail("section " + std::string(name) + " has no " + end);
    r.skip_bytes(at + end.size() - r.offset(), "a skipped section");
  }

  mesh::Mesh parse() {
    bool have_format = false, have_nodes = false;
    while (true) {
      const std::string_view t = r.token();
      if (t.empty()) break;
      if (t == "$MeshFormat") {
        mesh_format();
        have_format = true;
      } else if (!have_format) {
        r.fail("not a Gmsh MSH file (no $MeshFormat at the start)");
      } else if (t == "$Entities" && version >= 4.0) {
        entities_v41();
      } else if (t == "$Nodes") {
        version >= 4.0 ? nodes_v41() : nodes_v22();
        have_nodes = true;
      } else if (t == "$Elements") {
        if (!have_nodes) r.fail("$Elements before $Nodes");
        version >= 4.0 ? elements_v41() : elements_v22();
      } else if (t.size() > 1 && t[0] == '$') {
        skip_section(t);
      } else {
        r.fail("unexpected '" + std::string(t.substr(0, 40)) + "' between sections");
      }
    }
    if (!have_format) r.fail("not a Gmsh MSH file (empty)");
    RowMatX nodes(static_cast<Eigen::Index>(xyz.size() / 3), 3);
    for (Eigen::Index i = 0; i < nodes.size(); ++i) nodes.data()[i] = xyz[static_cast<size_t>(i)];
    return detail::assemble(r.name(), nodes, std::move(raw));
  }
};

int gmsh_type(mesh::ElementKind kind) {
  switch (kind) {
    case mesh::ElementKind::kQuad: return 3;
    case mesh::ElementKind::kTet: return 4;
    default: return 2;
  }
}

template <typename T>
void put(std::ostream& out, T v) {
  out.write(reinterpret_cast<const char*>(&v), sizeof(T));
}

void write_v22(std::ostream& out, const mesh::Mesh& m, bool binary) {
  const int nv = m.node_count(), ne = m.element_count(), npe = mesh::nodes_per_element(m.kind);
  out << "$MeshFormat\n2.2 " << (binary ? 1 : 0) << " 8\n";
  if (binary) {
    put<int>(out, 1);
    out << "\n";
  }
  out << "$EndMeshFormat\n$Nodes\n" << nv << "\n";
  out << std::setprecision(17);
  for (int i = 0; i < nv; ++i) {
    const double z = m.dim() == 3 ? m.nodes(i, 2) : 0.0;
    if (binary) {
      put<int>(out, i + 1);
      put<double>(out, m.nodes(i, 0));
      put<double>(out, m.nodes(i, 1));
      put<double>(out, z);
    } else {
      out << i + 1 << ' ' << m.nodes(i, 0) << ' ' << m.nodes(i, 1) << ' ' << z << '\n';
    }
  }
  if (binary) out << "\n";
  out << "$EndNodes\n$Elements\n" << ne << "\n";
  const int type = gmsh_type(m.kind);
  if (binary) {
    put<int>(out, type);
    put<int>(out, ne);
    put<int>(out, 2);
  }
  for (int e = 0; e < ne; ++e) {
    const int region = m.region.size() == ne ? m.region(e) : 0;
    if (binary) {
      put<int>(out, e + 1);
      put<int>(out, region);
      put<int>(out, region == 0 ? 1 : region);
      for (int k = 0; k < npe; ++k) put<int>(out, m.elements(e, k) + 1);
    } else {
      out << e + 1 << ' ' << type << " 2 " << region << ' ' << (region == 0 ? 1 : region);
      for (int k = 0; k < npe; ++k) out << ' ' << m.elements(e, k) + 1;
      out << '\n';
    }
  }
  if (binary) out << "\n";
  out << "$EndElements\n";
}

void write_v41(std::ostream& out, const mesh::Mesh& m, bool binary) {
  const int nv = m.node_count(), ne = m.element_count(), npe = mesh::nodes_per_element(m.kind);
  const int edim = m.kind == mesh::ElementKind::kTet ? 3 : 2;
  std::map<int, std::vector<int>> by_region;
  for (int e = 0; e < ne; ++e) by_region[m.region.size() == ne ? m.region(e) : 0].push_back(e);
  out << "$MeshFormat\n4.1 " << (binary ? 1 : 0) << " 8\n";
  if (binary) {
    put<int>(out, 1);
    out << "\n";
  }
  out << "$EndMeshFormat\n$Entities\n" << std::setprecision(17);
  const Eigen::RowVectorXd lo = m.nodes.colwise().minCoeff(), hi = m.nodes.colwise().maxCoeff();
  auto bound = [&](int c, bool upper) { return c < m.dim() ? (upper ? hi(c) : lo(c)) : 0.0; };
  const std::uint64_t nent = by_region.size();
  if (binary) {
    for (int d = 0; d < 4; ++d) put<std::uint64_t>(out, d == edim ? nent : 0);
  } else {
    for (int d = 0; d < 4; ++d) out << (d == edim ? nent : 0) << (d == 3 ? '\n' : ' ');
  }
  int tag = 1;
  for (const auto& [region, elems] : by_region) {
    if (binary) {
      put<int>(out, tag);
      for (int c = 0; c < 3; ++c) put<double>(out, bound(c, false));
      for (int c = 0; c < 3; ++c) put<double>(out, bound(c, true));
      put<std::uint64_t>(out, region != 0 ? 1 : 0);
      if (region != 0) put<int>(out, region);
      put<std::uint64_t>(out, 0);
    } else {
      out << tag;
      for (int c = 0; c < 3; ++c) out << ' ' << bound(c, false);
      for (int c = 0; c < 3; ++c) out << ' ' << bound(c, true);
      out << ' ' << (region != 0 ? 1 : 0);
      if (region != 0) out << ' ' << region;
      out << " 0\n";
    }
    ++tag;
  }
  if (binary) out << "\n";
  out << "$EndEntities\n$Nodes\n";
  if (binary) {
    for (std::uint64_t v : {std::uint64_t{1}, std::uint64_t(nv), std::uint64_t{1}, std::uint64_t(nv)}) put(out, v);
    put<int>(out, edim);
    put<int>(out, 1);
    put<int>(out, 0);
    put<std::uint64_t>(out, static_cast<std::uint64_t>(nv));
    for (int i = 0; i < nv; ++i) put<std::uint64_t>(out, static_cast<std::uint64_t>(i + 1));
    for (int i = 0; i < nv; ++i)
      for (int c = 0; c < 3; ++c) put<double>(out, c < m.dim() ? m.nodes(i, c) : 0.0);
    out << "\n";
  } else {
    out << "1 " << nv << " 1 " << nv << "\n" << edim << " 1 0 " << nv << "\n";
    for (int i = 0; i < nv; ++i) out << i + 1 << '\n';
    for (int i = 0; i < nv; ++i)
      out << m.nodes(i, 0) << ' ' << m.nodes(i, 1) << ' ' << (m.dim() == 3 ? m.nodes(i, 2) : 0.0) << '\n';
  }
  out << "$EndNodes\n$Elements\n";
  const int type = gmsh_type(m.kind);
  if (binary) {
    for (std::uint64_t v : {std::uint64_t(nent), std::uint64_t(ne), std::uint64_t{1}, std::uint64_t(ne)}) put(out, v);
  } else {
    out << nent << ' ' << ne << " 1 " << ne << '\n';
  }
  tag = 1;
  for (const auto& [region, elems] : by_region) {
    if (binary) {
      put<int>(out, edim);
      put<int>(out, tag);
      put<int>(out, type);
      put<std::uint64_t>(out, elems.size());
      for (int e : elems) {
        put<std::uint64_t>(out, static_cast<std::uint64_t>(e + 1));
        for (int k = 0; k < npe; ++k) put<std::uint64_t>(out, static_cast<std::uint64_t>(m.elements(e, k) + 1));
      }
    } else {
      out << edim << ' ' << tag << ' ' << type << ' ' << elems.size() << '\n';
      for (int e : elems) {
        out << e + 1;
        for (int k = 0; k < npe; ++k) out << ' ' << m.elements(e, k) + 1;
        out << '\n';
      }
    }
    ++tag;
  }
  if (binary) out << "\n";
  out << "$EndElements\n";
}

}  // namespace

mesh::Mesh read_msh(const std::filesystem::path& path) {
  Reader r = Reader::open(path);
  MshParser parser(r);
  return parser.parse();
}

void write_msh(const std::filesystem::path& path, const mesh::Mesh& mesh, MshVersion version, bool binary) {
  write_file_atomically(
      path,
      [&](std::ostream& out) {
        version == MshVersion::kV22 ? write_v22(out, mesh, binary) : write_v41(out, mesh, binary);
      },
      true);
}

}  // namespace hooke::io
