#include <hooke/core/error.hpp>
#include <hooke/identify/reference_file.hpp>
#include <hooke/io/csv.hpp>
#include <hooke/io/vtu.hpp>
#include <hooke/mesh/measure.hpp>
#include <string>

namespace hooke::identify {

void write_reference(const std::filesystem::path& path, const mesh::Mesh& mesh, const ReferenceCase& reference) {
  const int d = mesh.dim();
  const VecX rest = mesh::flat_positions(mesh);
  validate_reference(reference, rest.size());
  io::Field displacement{"displacement", d, reference.positions - rest};
  io::Field force{"force", d, reference.external_force};
  io::Field fixed{"fixed", 1, VecX::Zero(mesh.node_count())};
  io::Field prescribed{"prescribed", 1, VecX::Zero(mesh.node_count())};
  for (int n = 0; n < mesh.node_count(); ++n) {
    fixed.values(n) = reference.fixed_dofs[static_cast<std::size_t>(d * n)] ? 1.0 : 0.0;
    if (fixed.values(n) != 0.0) force.values.segment(d * n, d).setZero();
    if (!reference.prescribed_dofs.empty() && reference.prescribed_dofs[static_cast<std::size_t>(d * n)])
      prescribed.values(n) = 1.0;
  }
  std::vector<io::Field> fields{displacement, force, fixed};
  if (has_prescribed(reference)) fields.push_back(prescribed);  // files of traction cases stay as they were
  if (path.extension() == ".csv")
    io::write_node_csv(path, mesh, fields);
  else
    io::write_vtu(path, mesh, fields);
}

namespace {

// Per node: displacement (m), force (N) and the fixed flag, from a reference file, with the file's nodes checked
// against the mesh's.
struct ReferenceArrays {
  RowMatX nodes, displacement, force;
  VecX fixed, prescribed;
};

ReferenceArrays reference_from_vtu(const std::filesystem::path& path, int d) {
  const io::VtuContents vtu = io::read_vtu(path);
  const int n = vtu.mesh.node_count();
  ReferenceArrays a{vtu.mesh.nodes.leftCols(std::min<Eigen::Index>(d, vtu.mesh.nodes.cols())), RowMatX(n, d),
                    RowMatX(n, d), VecX::Zero(n), VecX::Zero(n)};
  const auto field = [&](const std::string& name, int components, RowMatX* rows, VecX* column) {
    for (const auto& f : vtu.point_data)
      if (f.name == name) {
        if (f.values.size() != static_cast<Eigen::Index>(f.components) * n || f.components < components)
          throw InvalidArgument(path.string() + ": point data '" + name + "' needs " + std::to_string(components) +
                                " components per point");
        for (int i = 0; i < n; ++i)
          for (int k = 0; k < components; ++k) (rows ? (*rows)(i, k) : (*column)(i)) = f.values(f.components * i + k);
        return;
      }
    if (rows) throw InvalidArgument(path.string() + ": no point data '" + name + "' (displacement in m, force in N)");
  };
  field("displacement", d, &a.displacement, nullptr);
  field("force", d, &a.force, nullptr);
  field("fixed", 1, nullptr, &a.fixed);
  field("prescribed", 1, nullptr, &a.prescribed);
  return a;
}

ReferenceArrays reference_from_csv(const std::filesystem::path& path, int d) {
  const io::CsvTable t = io::read_csv_table(path);
  static const char* kAxis[] = {"x", "y", "z"};
  const auto column = [&](const std::string& name) {
    const int c = t.column(name);
    if (c < 0)
      throw InvalidArgument(path.string() + ": no column '" + name + "' (node, x, y, z, displacement_x .. " +
                            "displacement_z in m, force_x .. force_z in N, optionally fixed)");
    return t.values.col(c);
  };
  const Eigen::Index n = t.values.rows();
  ReferenceArrays a{RowMatX(n, d), RowMatX(n, d), RowMatX(n, d), VecX::Zero(n), VecX::Zero(n)};
  const auto node = column("node");
  for (Eigen::Index i = 0; i < n; ++i)
    if (node(i) != static_cast<double>(i))
      throw InvalidArgument(path.string() + ": row " + std::to_string(i + 1) + " is node " + std::to_string(node(i)) +
                            "; rows must list nodes 0, 1, 2, ... in order");
  for (int k = 0; k < d; ++k) {
    a.nodes.col(k) = column(kAxis[k]);
    a.displacement.col(k) = column(std::string("displacement_") + kAxis[k]);
    a.force.col(k) = column(std::string("force_") + kAxis[k]);
  }
  if (t.column("fixed") >= 0) a.fixed = column("fixed");
  if (t.column("prescribed") >= 0) a.prescribed = column("prescribed");
  return a;
}

}  // namespace

ReferenceCase read_reference(const std::filesystem::path& path, const mesh::Mesh& mesh) {
  const int d = mesh.dim(), n = mesh.node_count();
  const std::string where = path.string();
  const ReferenceArrays a = path.extension() == ".csv" ? reference_from_csv(path, d) : reference_from_vtu(path, d);
  if (a.nodes.rows() != n)
    throw InvalidArgument(where + ": " + std::to_string(a.nodes.rows()) + " points where the mesh has " +
                          std::to_string(n) + " nodes");
  const double tolerance = 1e-9 * mesh::bounding_box_diagonal(mesh);
  for (int i = 0; i < n; ++i)
    if ((a.nodes.row(i) - mesh.nodes.row(i)).norm() > tolerance)
      throw InvalidArgument(where + ": point " + std::to_string(i) + " is not at node " + std::to_string(i) + " of " +
                            mesh.source);
  ReferenceCase c{path.filename().string(),
                  VecX(d * n),
                  VecX(d * n),
                  std::vector<char>(static_cast<std::size_t>(d * n), 0),
                  false,
                  {}};
  if (a.prescribed.size() && (a.prescribed.array() != 0.0).any())
    c.prescribed_dofs.assign(static_cast<std::size_t>(d * n), 0);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < d; ++k) {
      c.positions(d * i + k) = mesh.nodes(i, k) + a.displacement(i, k);
      c.external_force(d * i + k) = a.force(i, k);
      if (a.fixed(i) != 0.0) c.fixed_dofs[static_cast<std::size_t>(d * i + k)] = 1;
      if (!c.prescribed_dofs.empty() && a.prescribed(i) != 0.0)
        c.prescribed_dofs[static_cast<std::size_t>(d * i + k)] = 1;
    }
  validate_reference(c, d * n);
  return c;
}

}  // namespace hooke::identify
