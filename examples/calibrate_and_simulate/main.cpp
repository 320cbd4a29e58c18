// Uses hooke as a library: read a mesh, calibrate a spring model from E and nu, certify it against FEM, simulate
// 100 steps under gravity with the bottom clamped, and print the tip displacement.
//   calibrate_and_simulate MESH [E_PA NU]
#include <cstdio>
#include <exception>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/core/error.hpp>
#include <hooke/experiments/certify.hpp>
#include <hooke/io/mesh_io.hpp>
#include <hooke/solve/simulation.hpp>
#include <string>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s MESH [E_PA NU]\n", argv[0]);
    return 2;
  }
  try {
    const hooke::mesh::Mesh mesh = hooke::io::read_mesh(argv[1]);
    hooke::material::Material material;
    material.youngs_modulus = argc > 2 ? std::stod(argv[2]) : 14630.0;
    material.poisson_ratio = argc > 3 ? std::stod(argv[3]) : 0.25;
    hooke::calibrate::ModelOptions options;
    options.method = "lloyd-tet";
    hooke::calibrate::CalibratedModel model = hooke::calibrate::calibrate_model(mesh, material, options);
    model.certificate = hooke::experiments::certify(model);
    std::printf("%zu springs; against the linear FEM at 1 %% strain:\n", model.springs.pairs.size());
    for (const auto& c : model.certificate)
      std::printf("  %-8s max error %.3e m, relative L2 %.3f\n", c.load.c_str(), c.max_error, c.relative_l2);

    hooke::solve::SimulationOptions run;
    run.simulator.integrator = hooke::solve::Integrator::kLocalGlobal;
    run.steps = 100;
    run.dynamics.gravity = true;
    run.dynamics.damping_mass = 5.0;
    hooke::VecX last;
    const auto summary =
        hooke::solve::simulate(model, run, [&](int, double, const hooke::VecX& u, const hooke::VecX&) { last = u; });
    int tip = 0;  // the highest node
    for (int i = 1; i < mesh.node_count(); ++i)
      if (mesh.nodes(i, 2) > mesh.nodes(tip, 2)) tip = i;
    std::printf("after %zu steps (%.3f s): tip node %d moved %.6e m down\n", summary.step_ms.size(), summary.time, tip,
                -last(3 * tip + 2));
    return 0;
  } catch (const hooke::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "internal error: %s\n", e.what());
    return 4;
  }
}
