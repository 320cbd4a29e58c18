// hooke fem MESH --young PA --poisson NU [...] -o OUT.vtu: the FEM reference on one load case.
#include <cmath>
#include <cstdio>
#include <hooke/core/error.hpp>
#include <hooke/core/output_transaction.hpp>
#include <hooke/core/units.hpp>
#include <hooke/fem/elastic_block.hpp>
#include <hooke/io/csv.hpp>
#include <hooke/io/mesh_io.hpp>
#include <hooke/io/vtu.hpp>
#include <hooke/model/load_case.hpp>
#include <hooke/solve/static_equilibrium.hpp>
#include <hooke/solve/strain_response.hpp>
#include <memory>
#include <string>

#include "commands.hpp"

namespace hooke::cli {
namespace {

struct FemOptions {
  ModelInput in;
  std::string output, csv, load = "stretch", law = "linear", plane = "stress", control = "traction";
  double traction = std::nan(""), strain = std::nan("");
};

// The VTU (and the CSV) as one transaction: both or neither (a failing --csv no longer leaves the VTU).
void write_outputs(const FemOptions& o, const mesh::Mesh& m, const VecX& u, const VecX& external_force) {
  const io::Field displacement{"displacement", m.dim(), u};
  VecX magnitude(m.node_count());
  for (int i = 0; i < m.node_count(); ++i) magnitude(i) = u.segment(m.dim() * i, m.dim()).norm();
  OutputTransaction outputs;
  io::write_vtu(outputs.stage_file(o.output), m,
                {displacement, {"displacement_magnitude", 1, magnitude}, {"external_force", m.dim(), external_force}});
  if (!o.csv.empty()) io::write_node_csv(outputs.stage_file(o.csv), m, {displacement});
  outputs.commit();
  std::printf("  wrote     %s\n", o.output.c_str());
  if (!o.csv.empty()) std::printf("  wrote     %s\n", o.csv.c_str());
}

int run_fem(const FemOptions& o) {
  io::ReadOptions ro;
  ro.metres_per_unit = metres_per_unit(o.in.unit);
  const mesh::Mesh m = io::read_mesh(o.in.mesh_path, ro);
  material::Material mat;
  mat.law = material::law_from_name(o.law);
  mat.youngs_modulus = o.in.young;
  mat.poisson_ratio = o.in.poisson;
  mat.thickness = o.in.thickness;
  mat.plane = material::plane_from_name(o.plane);
  material::validate(mat);
  const model::LoadKind kind = model::load_kind_from_name(o.load);
  const model::LoadControl control = model::load_control_from_name(o.control);
  if (std::isnan(o.traction) == std::isnan(o.strain))
    throw InvalidArgument("give exactly one of --traction and --strain");
  model::LoadCase lc;
  double traction = 0.0;
  if (control == model::LoadControl::kDisplacement) {  // the top moved rigidly by strain x height
    if (std::isnan(o.strain) || !(o.strain > 0.0))
      throw InvalidArgument("--control displacement needs --strain S > 0 (the top moved by S x height)");
    lc = model::make_displacement_case(m, kind, 0.0, mat.thickness);
    lc.displacement = o.strain * lc.height;
  } else {
    traction = std::isnan(o.strain) ? o.traction : solve::traction_for_strain(m, {mat}, kind, o.strain);
    lc = model::make_load_case(m, kind, traction, mat.thickness);
  }

  const auto model = fem::elastic_model(m, {mat});
  model::Problem problem = model::make_problem(model);
  model::apply(lc, problem);
  solve::StaticOptions statics;
  statics.ramp_prescribed = true;  // a press or pull reached in load steps, never in one jump
  const solve::StaticResult r =
      mat.law == material::Law::kLinear ? solve::linear_static(problem) : solve::static_equilibrium(problem, statics);
  const solve::SolveReport& rep = r.report;

  std::printf("hooke fem: %s\n", o.in.mesh_path.c_str());
  std::printf("  mesh      %d nodes, %d %s elements, %d DOFs (%d free)\n", m.node_count(), m.element_count(),
              std::string(mesh::element_kind_name(m.kind)).c_str(), model->dof_count(), rep.free_dofs);
  std::printf("  material  %s, E = %g Pa, nu = %g%s\n", std::string(material::law_name(mat.law)).c_str(),
              mat.youngs_modulus, mat.poisson_ratio,
              m.dim() == 2 ? (", plane " + o.plane + ", t = " + std::to_string(mat.thickness) + " m").c_str() : "");
  if (control == model::LoadControl::kDisplacement)
    std::printf("  load      %s, top moved %.6g m (%.4g %% of height %.6g m), %zu clamped nodes\n", o.load.c_str(),
                lc.displacement, 100.0 * o.strain, lc.height, lc.fixed_nodes.size());
  else
    std::printf("  load      %s, traction %.6g Pa on %.6g m^2 of top boundary, height %.6g m, %zu clamped nodes\n",
                o.load.c_str(), traction, lc.top_area, lc.height, lc.fixed_nodes.size());
  std::printf("  solve     %s: %s\n", std::string(solve::status_name(rep.status)).c_str(), rep.message.c_str());
  std::printf("  timing    total %.4f s (assembly %.4f s, factorisation %.4f s, %s)\n", rep.solve_seconds,
              rep.assembly_seconds, rep.factorization_seconds, rep.backend.c_str());
  if (mat.law != material::Law::kLinear)
    std::printf("  newton    %d iterations, %d load steps, residual %.3g N, min tangent eigenvalue %.4g N/m\n",
                rep.iterations, rep.load_steps, rep.residual, rep.min_eigenvalue);
  solve::require_converged(rep);

  const VecX u = r.positions - model->rest_positions();
  double max_u = 0.0;
  for (int i = 0; i < m.node_count(); ++i) max_u = std::max(max_u, u.segment(m.dim() * i, m.dim()).norm());
  const double mean_top = model::mean_top_displacement(lc, problem, r.positions);
  std::printf("  result    max displacement %.6g m, mean top displacement along the load %.6g m (%.2f %% of height)\n",
              max_u, mean_top, 100.0 * mean_top / lc.height);
  const VecX reaction = model::top_reaction(lc, problem, r.positions);
  std::printf("  force     on the top %.6g N (|F| %.6g N)\n", reaction.dot(lc.direction), reaction.norm());
  write_outputs(o, m, u, problem.external_force);
  return 0;
}

}  // namespace

Action add_fem_command(CLI::App& app) {
  auto o = std::make_shared<FemOptions>();
  CLI::App* cmd = app.add_subcommand("fem", "Solve a load case with the FEM reference (linear, StVK or Neo-Hookean)");
  add_model_input_options(cmd, o->in);
  cmd->add_option("--plane", o->plane, "2D model: stress or strain")->capture_default_str();
  cmd->add_option("--load", o->load, "Load case: stretch, compress or shear")->capture_default_str();
  cmd->add_option("--traction", o->traction, "Traction on the top boundary, Pa");
  cmd->add_option("--strain", o->strain,
                  "Traction control: set the traction so that the linear FEM's mean top displacement is S x height; "
                  "displacement control: move the top by S x height");
  cmd->add_option("--control", o->control,
                  "traction (a dead load on the top) or displacement (the top moved rigidly; the force on it reported)")
      ->capture_default_str();
  cmd->add_option("--material", o->law, "Constitutive law: linear, stvk or neohookean")->capture_default_str();
  cmd->add_option("-o,--output", o->output, "Output .vtu with displacement")->required();
  cmd->add_option("--csv", o->csv, "Also write per-node displacements as CSV");
  return [o] { return run_fem(*o); };
}

}  // namespace hooke::cli
