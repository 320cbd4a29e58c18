#pragma once
// The benchmark body: tetrahedral cylinders (r 1 cm, h 2 cm; mesh::tet_cylinder) of 1 089, 11 025 and 103 275
// nodes with lloyd-tet springs (E 14 630 Pa, nu 0.25, 1 000 kg/m^3), bottom clamped, under gravity.
#include <hooke/calibrate/method.hpp>
#include <hooke/experiments/load_case.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/model/mass.hpp>
#include <hooke/solve/simulator.hpp>
#include <hooke/springs/spring_block.hpp>
#include <memory>

namespace hooke::bench {

struct Cylinder {
  mesh::Mesh mesh;
  std::shared_ptr<model::Model> model;
  model::Problem problem;    // bottom clamped, no loads
  solve::Dynamics dynamics;  // lumped masses, gravity -z, no damping
  const springs::SpringBlock* springs = nullptr;
  /// @param size  0, 1, 2: about 1 000, 10 000, 100 000 nodes
  explicit Cylinder(int size) {
    const int n[3] = {10, 20, 44}, layers[3] = {8, 24, 50};
    mesh = mesh::tet_cylinder(0.01, 0.02, n[size], layers[size]);
    model = calibrate::make_model(
        mesh, calibrate::calibrate(mesh, {{material::Law::kLinear, 14630.0, 0.25}}, calibrate::Method::kLloydTet));
    for (const auto& b : model->blocks())
      if (const auto* s = dynamic_cast<const springs::SpringBlock*>(b.get())) springs = s;
    problem = model::make_problem(model);
    model::fix_nodes(problem, experiments::make_load_case(mesh, experiments::LoadKind::kStretch, 0.0).fixed_nodes);
    VecX g = VecX::Zero(3);
    g(2) = -9.81;
    dynamics = {model::lumped_masses(mesh, 1000.0), g, 0.0, 0.0};
  }
};

}  // namespace hooke::bench
