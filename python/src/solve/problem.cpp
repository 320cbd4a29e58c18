#include <hooke/core/error.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/solve/strain_response.hpp>
#include <solve/problem.hpp>
#include <string>

namespace hooke::python {

void ProblemData::fix_nodes(const std::vector<int>& nodes) {
  for (int n : nodes)
    if (n < 0 || n >= problem.model->node_count())
      throw InvalidArgument("fix_nodes: node " + std::to_string(n) + " is not in the model (it has " +
                            std::to_string(problem.model->node_count()) + " nodes)");
  model::fix_nodes(problem, nodes);
}

void ProblemData::apply_load(model::LoadKind kind, double traction, double strain) {
  if (strain != 0.0 && !(strain > 0.0 && std::isfinite(strain)))
    throw InvalidArgument("apply_load: the strain must be a finite number > 0");
  if (!std::isfinite(traction)) throw InvalidArgument("apply_load: the traction must be finite");
  const double t = strain > 0.0
                       ? solve::traction_for_strain(model.mesh, calibrate::element_materials(model), kind, strain)
                       : traction;
  model::apply(model::make_load_case(model.mesh, kind, t, model.material.thickness), problem);
}

PyTool ProblemData::add_tool(const std::string& shape, const contact::Pose& pose, double distance,
                             contact::Friction friction) {
  auto tool = std::make_shared<contact::RigidTool>(contact::parse_tool(shape));
  tool->set_pose(pose);
  std::shared_ptr<contact::ContactBlock> block =
      contact::boundary_contact(model.mesh, model.material.youngs_modulus, tool, distance);
  if (friction.slip == 0.0) friction.slip = 1e-5 * mesh::bounding_box_diagonal(model.mesh);
  block->set_friction(friction);
  contacts.push_back(block);
  const calibrate::BuiltModel built = calibrate::build_model(model);
  for (const auto& c : contacts) built.model->add(std::make_unique<contact::ContactBlock>(*c));
  problem.model = built.model;
  return {tool, block, model.mesh.node_count()};
}

pybind11::array_t<double> ProblemData::rows(const VecX& flat) const {
  const int d = problem.model->dim();
  pybind11::array_t<double> a({static_cast<pybind11::ssize_t>(flat.size() / d), static_cast<pybind11::ssize_t>(d)});
  std::copy(flat.data(), flat.data() + flat.size(), a.mutable_data());
  return a;
}

}  // namespace hooke::python
