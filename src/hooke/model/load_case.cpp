#include <algorithm>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/core/name_table.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/mesh/topology.hpp>
#include <hooke/model/load_case.hpp>
#include <hooke/model/support.hpp>

namespace hooke::model {

namespace {
constexpr NameTable<LoadKind, 3> kLoadKinds{
    "load case", {{{LoadKind::kStretch, "stretch"}, {LoadKind::kCompress, "compress"}, {LoadKind::kShear, "shear"}}}};
constexpr NameTable<LoadControl, 2> kLoadControls{
    "load control", {{{LoadControl::kTraction, "traction"}, {LoadControl::kDisplacement, "displacement"}}}};
}  // namespace

LoadControl load_control_from_name(std::string_view name) { return kLoadControls.from_name(name); }
std::string_view load_control_name(LoadControl control) { return kLoadControls.name(control); }

LoadKind load_kind_from_name(std::string_view name) { return kLoadKinds.from_name(name); }
std::string_view load_kind_name(LoadKind kind) { return kLoadKinds.name(kind); }

LoadCase make_load_case(const mesh::Mesh& mesh, LoadKind kind, double traction_pa, double thickness) {
  if (!std::isfinite(traction_pa)) throw InvalidArgument("the traction must be a finite number of pascals");
  const int d = mesh.dim(), up = d - 1;
  LoadCase lc;
  lc.kind = kind;
  lc.traction_pa = traction_pa;
  lc.direction = VecX::Zero(d);
  switch (kind) {
    case LoadKind::kStretch: lc.direction(up) = 1.0; break;
    case LoadKind::kCompress: lc.direction(up) = -1.0; break;
    case LoadKind::kShear: lc.direction(d == 2 ? 0 : 1) = 1.0; break;
  }
  const RowMatXi facets = mesh::boundary_facets(mesh);
  const VecX measure = mesh::facet_measures(mesh, facets);
  lc.height = mesh.nodes.col(up).maxCoeff() - mesh.nodes.col(up).minCoeff();
  // The papers' faces, or for a curved body (no boundary facet wholly on the top face) its end bands.
  std::vector<int> loaded = end_facets(mesh, facets, up, End::kHigh, kFace);
  const double band = loaded.empty() ? kEndBand : kFace;
  if (band != kFace) loaded = end_facets(mesh, facets, up, End::kHigh, band);
  lc.fixed_nodes = end_nodes(mesh, up, End::kLow, band);
  lc.top_nodes = end_nodes(mesh, up, End::kHigh, band);
  lc.nodal_forces = VecX::Zero(d * mesh.node_count());
  for (int f : loaded) {
    const double area = measure(f) * (d == 2 ? thickness : 1.0);
    lc.top_area += area;
    const double share = traction_pa * area / static_cast<double>(facets.cols());
    for (Eigen::Index k = 0; k < facets.cols(); ++k)
      for (int c = 0; c < d; ++c) lc.nodal_forces(d * facets(f, k) + c) += share * lc.direction(c);
  }
  const std::string where = mesh.source.empty() ? std::string("the mesh") : mesh.source;
  if (loaded.empty()) throw InvalidArgument(where + " has no flat top boundary to load");
  if (lc.fixed_nodes.empty()) throw InvalidArgument(where + " has no bottom boundary to clamp");
  return lc;
}

LoadCase make_displacement_case(const mesh::Mesh& mesh, LoadKind kind, double displacement, double thickness) {
  if (!std::isfinite(displacement)) throw InvalidArgument("the displacement must be a finite number of metres");
  LoadCase lc = make_load_case(mesh, kind, 0.0, thickness);
  lc.control = LoadControl::kDisplacement;
  lc.displacement = displacement;
  lc.nodal_forces.setZero();
  return lc;
}

void apply(const LoadCase& load, Problem& problem) {
  if (load.nodal_forces.size() != problem.model->dof_count())
    throw InvalidArgument("load case and problem belong to different meshes");
  fix_nodes(problem, load.fixed_nodes);
  problem.external_force = load.nodal_forces;
  if (load.control == LoadControl::kDisplacement) {
    const int d = problem.model->dim();
    fix_nodes(problem, load.top_nodes);
    if (problem.prescribed_positions.size() != problem.model->dof_count())
      problem.prescribed_positions = problem.model->rest_positions();
    const std::vector<int>& fixed = load.fixed_nodes;
    for (int node : load.top_nodes)
      if (!std::binary_search(fixed.begin(), fixed.end(), node))
        problem.prescribed_positions.segment(d * node, d) += load.displacement * load.direction;
  }
  zero_fixed_forces(problem);
}

VecX top_reaction(const LoadCase& load, const Problem& problem, const VecX& positions) {
  const int d = problem.model->dim();
  const VecX g = problem.model->gradient(positions, problem.interaction_or_null());
  VecX sum = VecX::Zero(d);
  const std::vector<int>& fixed = load.fixed_nodes;
  for (int node : load.top_nodes)
    if (!std::binary_search(fixed.begin(), fixed.end(), node)) sum += g.segment(d * node, d);
  return sum;
}

double mean_top_displacement(const LoadCase& load, const Problem& problem, const VecX& positions) {
  const int d = problem.model->dim();
  const VecX u = positions - problem.model->rest_positions();
  double sum = 0.0;
  for (int node : load.top_nodes) sum += u.segment(d * node, d).dot(load.direction);
  return load.top_nodes.empty() ? 0.0 : sum / static_cast<double>(load.top_nodes.size());
}

}  // namespace hooke::model
