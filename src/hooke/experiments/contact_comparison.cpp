#include <cmath>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/contact/contact_block.hpp>
#include <hooke/core/error.hpp>
#include <hooke/experiments/contact_comparison.hpp>
#include <hooke/model/load_case.hpp>
#include <hooke/solve/tool_press.hpp>
#include <limits>
#include <memory>
#include <string>

namespace hooke::experiments {
namespace {

// The press on one model: its equilibria at every pose.
std::vector<solve::ToolPressStep> press(const calibrate::CalibratedModel& m, const contact::RigidTool& shape,
                                        const std::vector<contact::Pose>& poses, double activation,
                                        const std::string& name) {
  auto tool = std::make_shared<contact::RigidTool>(shape);
  tool->set_pose(poses.front());
  const calibrate::BuiltModel built = calibrate::build_model(m);
  auto block = contact::boundary_contact(m.mesh, m.material.youngs_modulus, tool, activation);
  const contact::ContactBlock& contact = *block;
  built.model->add(std::move(block));
  model::Problem problem = model::make_problem(built.model);
  model::fix_nodes(problem,
                   model::make_load_case(m.mesh, model::LoadKind::kStretch, 0.0, m.material.thickness).fixed_nodes);
  try {
    return solve::press_quasi_statically(problem, contact, *tool, poses);
  } catch (const SolverFailure& e) {
    throw SolverFailure(name + ": " + e.what());
  }
}

}  // namespace

std::vector<ContactPressRow> compare_under_contact(const calibrate::CalibratedModel& model,
                                                   const contact::RigidTool& tool, const ContactPressOptions& o) {
  if (model.surface || model.mesh.kind != mesh::ElementKind::kTet)
    throw InvalidArgument("a contact comparison needs a model of a tet mesh (the FEM is on the same tets)");
  if (!(o.depth > 0.0 && std::isfinite(o.depth))) throw InvalidArgument("the press depth must be > 0 m");
  if (o.steps < 1) throw InvalidArgument("the press needs at least one step");
  if (!(o.direction.norm() > 0.0) || !o.direction.allFinite())
    throw InvalidArgument("the press direction must be a non-zero vector");
  if (tool.shape() == contact::ToolShape::kHalfSpace) throw InvalidArgument("press with a sphere or a capsule");
  const Vec3 along = o.direction.normalized();
  std::vector<contact::Pose> poses;
  for (int k = 0; k <= o.steps; ++k)
    poses.push_back({o.start.position + (o.depth * k / o.steps) * along, o.start.rotation});
  // The same activation distance on both (the model's default for this mesh unless given).
  const double activation = o.contact_distance > 0.0
                                ? o.contact_distance
                                : contact::boundary_contact(model.mesh, model.material.youngs_modulus,
                                                            std::make_shared<contact::RigidTool>(tool))
                                      ->activation();
  material::Material material = model.material;
  material.law = o.reference;
  calibrate::ModelOptions fem_options;
  fem_options.method = calibrate::model_kind_name(calibrate::ModelKind::kFem);
  fem_options.density = model.density;
  fem_options.regions = model.regions;
  const calibrate::CalibratedModel fem = calibrate::calibrate_model(model.mesh, material, fem_options);
  const auto f = press(fem, tool, poses, activation, "the FEM (" + std::string(material::law_name(o.reference)) + ")");
  const auto s = press(model, tool, poses, activation, "the " + model.method + " model");
  const VecX rest = mesh::flat_positions(model.mesh);
  std::vector<ContactPressRow> rows;
  for (std::size_t k = 1; k < poses.size(); ++k) {
    ContactPressRow r;
    r.travel = o.depth * static_cast<double>(k) / o.steps;
    r.fem_force = f[k].tool_force;
    r.model_force = s[k].tool_force;
    r.force_error = r.fem_force.norm() > 0.0 ? (r.model_force - r.fem_force).norm() / r.fem_force.norm() : 0.0;
    const double moved = (f[k].positions - rest).norm();
    r.relative_l2 = moved > 0.0 ? (s[k].positions - f[k].positions).norm() / moved : 0.0;
    r.fem_contacts = f[k].active;
    r.model_contacts = s[k].active;
    r.smallest_gap = std::min(f[k].smallest_distance, s[k].smallest_distance);
    rows.push_back(r);
  }
  return rows;
}

}  // namespace hooke::experiments
