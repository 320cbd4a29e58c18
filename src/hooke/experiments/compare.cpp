#include <hooke/core/error.hpp>
#include <hooke/experiments/compare.hpp>
#include <hooke/fem/elastic_block.hpp>

namespace hooke::experiments {

Comparison compare(const mesh::Mesh& mesh, const std::vector<material::Material>& materials,
                   const CompareOptions& options) {
  std::vector<material::Material> reference = materials;
  for (auto& m : reference) m.law = options.reference;
  const double thickness = materials.at(0).thickness;
  const double traction = options.strain > 0.0 ? traction_for_strain(mesh, materials[0], options.load, options.strain)
                                               : options.traction_pa;
  Comparison c;
  c.load = make_load_case(mesh, options.load, traction, thickness);

  auto fem_model =
      std::make_shared<model::Model>(mesh.dim(), Eigen::Map<const VecX>(mesh.nodes.data(), mesh.nodes.size()));
  fem_model->add(std::make_unique<fem::ElasticBlock>(mesh, reference));
  model::Problem fem_problem = model::make_problem(fem_model);
  apply(c.load, fem_problem);
  const solve::StaticResult fem = options.reference == material::Law::kLinear ? solve::linear_static(fem_problem)
                                                                              : solve::static_equilibrium(fem_problem);

  c.springs = calibrate::calibrate(mesh, materials, options.method);
  model::Problem spring_problem = model::make_problem(calibrate::make_model(mesh, c.springs));
  apply(c.load, spring_problem);
  const solve::StaticResult springs = solve::static_equilibrium(spring_problem);

  c.fem_positions = fem.positions;
  c.spring_positions = springs.positions;
  c.fem_report = fem.report;
  c.spring_report = springs.report;
  const int d = mesh.dim();
  c.node_error.resize(mesh.node_count());
  for (int i = 0; i < mesh.node_count(); ++i)
    c.node_error(i) = (c.spring_positions.segment(d * i, d) - c.fem_positions.segment(d * i, d)).norm();
  c.max_error = c.node_error.maxCoeff();
  c.mean_error = c.node_error.mean();
  return c;
}

}  // namespace hooke::experiments
