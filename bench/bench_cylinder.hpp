#pragma once
// The benchmark body: experiments::benchmark_cylinder (r 1 cm, h 2 cm; 1 089, 11 425 and 103 066 nodes) with
// lloyd-tet springs (E 14 630 Pa, nu 0.25, 1 000 kg/m^3), bottom clamped, under gravity; the same model as
// `hooke bench`, from the library's model factory.
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/experiments/dynamics_benchmark.hpp>
#include <hooke/model/load_case.hpp>
#include <hooke/solve/simulator.hpp>
#include <hooke/springs/spring_block.hpp>
#include <memory>

namespace hooke::bench {

struct Cylinder {
  mesh::Mesh mesh;
  std::shared_ptr<model::Model> model;
  model::Problem problem;                         // bottom clamped, no loads
  solve::Dynamics dynamics;                       // lumped masses, gravity -z, no damping
  std::unique_ptr<springs::SpringBlock> springs;  // the model's springs alone, for the force-throughput case
  /// @param size  0, 1, 2: about 1 000, 10 000, 100 000 nodes
  explicit Cylinder(int size) {
    const calibrate::CalibratedModel cm = experiments::benchmark_model(size);
    mesh = cm.mesh;
    model = calibrate::build_model(cm).model;
    springs = std::make_unique<springs::SpringBlock>(3, cm.springs.pairs, cm.springs.stiffness, cm.springs.rest_length);
    problem = model::make_problem(model);
    model::fix_nodes(problem, model::make_load_case(mesh, model::LoadKind::kStretch, 0.0).fixed_nodes);
    VecX g = VecX::Zero(3);
    g(2) = -9.81;
    dynamics = {cm.masses, g, 0.0, 0.0};
  }
};

}  // namespace hooke::bench
