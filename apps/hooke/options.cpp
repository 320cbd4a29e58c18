#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/calibrate/model_file.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/units.hpp>
#include <hooke/io/mesh_io.hpp>
#include <hooke/solve/simulator_settings.hpp>

#include "commands.hpp"

namespace hooke::cli {

void require_finite_numbers(const CLI::App& app) {
  for (const CLI::Option* opt : app.get_options()) {
    if (opt->count() == 0 || opt->get_type_name().find("FLOAT") == std::string::npos) continue;
    for (const std::string& text : opt->results()) {
      const double v = std::strtod(text.c_str(), nullptr);
      if (!std::isfinite(v)) throw InvalidArgument(opt->get_name() + " must be a finite number, found '" + text + "'");
    }
  }
  for (const CLI::App* sub : app.get_subcommands()) require_finite_numbers(*sub);
}

void add_model_input_options(CLI::App* cmd, ModelInput& in) {
  cmd->add_option("mesh", in.mesh_path, "Mesh file (.msh, .vtu, .node/.ele, .obj, .off, .stl)")->required();
  cmd->add_option("--young", in.young, "Young's modulus E, Pa")->required();
  cmd->add_option("--poisson", in.poisson, "Poisson's ratio nu, in (-1, 0.5)")->required();
  cmd->add_option("--unit", in.unit, "Length unit of the mesh file (and of printed lengths): m, cm, mm, um")
      ->capture_default_str();
  cmd->add_option("--thickness", in.thickness, "Plate thickness for 2D meshes, m")->capture_default_str();
}

void add_surface_options(CLI::App* cmd, SurfaceInput& in) {
  cmd->add_option("--scheme", in.scheme, "surface: scheme A, B, C or D")->capture_default_str();
  cmd->add_option("--anchor-law", in.anchor_law, "surface: single, blend or tensor (default: the scheme's)");
  cmd->add_option("--volume-force", in.volume_force, "surface: nodal, printed or energy")->capture_default_str();
  cmd->add_option("--centre", in.centre, "surface: object centre x,y,z in m (default: the volume centroid)")
      ->delimiter(',');
}

calibrate::SurfaceOptions surface_options(const SurfaceInput& in) {
  calibrate::SurfaceOptions o;
  o.scheme = calibrate::surface_scheme_from_name(in.scheme);
  if (!in.anchor_law.empty()) o.anchor_law = surface::anchor_law_from_name(in.anchor_law);
  o.volume_force = surface::volume_force_from_name(in.volume_force);
  if (!in.centre.empty()) {
    if (in.centre.size() != 3) throw InvalidArgument("--centre needs three components x,y,z (m)");
    o.centre = Vec3(in.centre[0], in.centre[1], in.centre[2]);
  }
  return o;
}

void add_tetrahedralize_options(CLI::App* cmd, TetrahedralizeInput& in) {
  const std::string group = "Closed surface to tets";
  cmd->add_option("--mesher", in.mesher,
                  "netgen (linked, the default) or tetgen (TetGen's program on files, about 8x faster on large "
                  "scans, keeps the surface; Debian's tetgen program, never linked)")
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--size", in.size, "Largest tet edge inside the body, in the mesh unit (default: diagonal / 25)")
      ->group(group);
  cmd->add_option("--max-volume", in.max_volume,
                  "Largest tet volume, in the mesh unit cubed (instead of --size: the edge of the regular tet)")
      ->group(group);
  cmd->add_option("--quality", in.options.min_radius_ratio,
                  "Quality floor: refuse the mesh if a tet's radius ratio (1 regular, 0 flat) is below it; 0 reports")
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--surface-mesh", in.surface_mesh,
                  "keep (the scan's triangles bound the tets: nodes and volume exact) or remesh (Netgen remeshes "
                  "the surface at --size first)")
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--fineness", in.options.fineness, "Netgen fineness, 0 (coarse) .. 1 (fine)")
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--grading", in.options.grading, "Netgen grading, 0 (uniform) .. 1 (aggressive)")
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--optimisation-steps", in.options.optimisation_steps, "Netgen volume optimisation passes")
      ->capture_default_str()
      ->group(group);
}

mesh::TetrahedralizeOptions tetrahedralize_options(const TetrahedralizeInput& in, double metres_per_unit) {
  mesh::TetrahedralizeOptions o = in.options;
  o.surface = mesh::surface_meshing_from_name(in.surface_mesh);
  o.mesher = mesh::mesher_from_name(in.mesher);
  mesh::set_mesh_size(o, in.size * metres_per_unit,
                      in.max_volume * metres_per_unit * metres_per_unit * metres_per_unit);
  return o;
}

void add_term_law_options(CLI::App* cmd, double& spring_exponent, double& volume_exponent) {
  cmd->add_option("--spring-exponent", spring_exponent,
                  "Springs' large-strain law: Seth-Hill exponent m of E = k l0^2 e_m(l/l0)^2 / 2 (1: Hookean)")
      ->capture_default_str();
  cmd->add_option("--volume-exponent", volume_exponent,
                  "Volume terms' large-strain law: Seth-Hill exponent q of E = k_V e_q(V/V0)^2 / 2 (1: quadratic, "
                  "<= 0: a barrier against flattening)")
      ->capture_default_str();
}

void add_model_source_options(CLI::App* cmd, ModelSource& in) {
  cmd->add_option("mesh", in.mesh_path,
                  "Mesh file (.msh, .vtu, .node/.ele, .obj, .off, .stl; a closed surface is tetrahedralized for every "
                  "method but surface), or a model file (.json, as --model); optional with --model");
  cmd->add_option("--model", in.model_path,
                  "Model file (.json, from hooke calibrate or written by hand) instead of "
                  "--method, --young and --poisson");
  cmd->add_option("--young", in.young, "Young's modulus E, Pa");
  cmd->add_option("--poisson", in.poisson, "Poisson's ratio nu, in (-1, 0.5)");
  std::string methods;
  for (const auto& n : calibrate::model_method_names()) methods += (methods.empty() ? "" : ", ") + n;
  cmd->add_option("--method", in.method, "Model: " + methods)->capture_default_str();
  cmd->add_option("--unit", in.unit, "Length unit of the mesh file (and of printed lengths): m, cm, mm, um")
      ->capture_default_str();
  cmd->add_option("--thickness", in.thickness, "Plate thickness for 2D meshes, m")->capture_default_str();
  cmd->add_option("--density", in.density, "Density for the lumped masses, kg/m^3")->capture_default_str();
  cmd->add_option("--plane", in.plane, "2D models: stress or strain")->capture_default_str();
  add_term_law_options(cmd, in.spring_exponent, in.volume_exponent);
  add_surface_options(cmd, in.surface);
  add_tetrahedralize_options(cmd, in.tetrahedralize);
}

calibrate::CalibratedModel load_model(const ModelSource& source) {
  // A model file given where the mesh goes (hooke view m.json) is read as --model.
  ModelSource in = source;
  if (in.model_path.empty() && std::filesystem::path(in.mesh_path).extension() == ".json") {
    in.model_path = in.mesh_path;
    in.mesh_path.clear();
  }
  io::ReadOptions ro;
  ro.metres_per_unit = metres_per_unit(in.unit);
  if (!in.model_path.empty()) {
    if (!std::isnan(in.young) || !std::isnan(in.poisson))
      throw InvalidArgument("--model carries its material: drop --young and --poisson");
    calibrate::CalibratedModel model = calibrate::read_model(in.model_path);
    if (!in.mesh_path.empty()) calibrate::require_same_nodes(model, io::read_mesh(in.mesh_path, ro));
    return model;
  }
  if (in.mesh_path.empty()) throw InvalidArgument("give a mesh file (or --model MODEL.json)");
  if (std::isnan(in.young) || std::isnan(in.poisson))
    throw InvalidArgument("--young and --poisson are required (or --model MODEL.json)");
  // The law is the FEM model's (--method fem); every calibration starts from the linear material.
  material::Material mat{in.method == "fem" ? material::law_from_name(in.law) : material::Law::kLinear, in.young,
                         in.poisson, material::plane_from_name(in.plane), in.thickness};
  calibrate::ModelOptions mo;
  mo.method = in.method;
  mo.density = in.density;
  mo.spring_exponent = in.spring_exponent;
  mo.volume_exponent = in.volume_exponent;
  if (in.method == "surface" || in.method == "auto") mo.surface = surface_options(in.surface);
  mo.tetrahedralize = tetrahedralize_options(in.tetrahedralize, ro.metres_per_unit);
  calibrate::CalibratedModel model = calibrate::calibrate_model(io::read_mesh(in.mesh_path, ro), mat, mo);
  if (!model.meshing.empty()) std::fprintf(stderr, "hooke: tetrahedralized: %s\n", model.meshing.c_str());
  if (!model.choice.empty()) std::fprintf(stderr, "hooke: %s\n", model.choice.c_str());  // what --method auto picked
  return model;
}

int parse_and_run(CLI::App& app, int argc, char** argv, const char* program, const std::function<int()>& action) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    require_finite_numbers(app);
    return action();
  } catch (const SolverFailure& e) {
    std::fprintf(stderr, "%s: solver failure: %s\n", program, e.what());
    return 3;
  } catch (const Error& e) {
    std::fprintf(stderr, "%s: error: %s\n", program, e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: internal error: %s\n", program, e.what());
    return 4;
  }
}

void add_dynamics_options(CLI::App* cmd, solve::DynamicsSetup& setup) {
  for (const solve::DynamicsField& f : solve::dynamics_fields()) {
    const std::string flag = "--" + std::string(f.name), help(f.help);
    if (f.number)
      cmd->add_option(flag, setup.*f.number, help)->capture_default_str();
    else
      cmd->add_flag(flag, setup.*f.flag, help);
  }
}

void add_integrator_options(CLI::App* cmd, IntegratorInput& in, const solve::SimulatorOptions& options) {
  const std::span<const solve::SimulatorField> fields = solve::simulator_fields();
  in.values.assign(fields.size(), std::string());
  for (size_t k = 0; k < fields.size(); ++k)
    cmd->add_option("--" + std::string(fields[k].name), in.values[k], std::string(fields[k].help))
        ->default_str(fields[k].get(options));
}

void apply_integrator_options(const IntegratorInput& in, solve::SimulatorOptions& options) {
  const std::span<const solve::SimulatorField> fields = solve::simulator_fields();
  for (size_t k = 0; k < in.values.size() && k < fields.size(); ++k)
    if (!in.values[k].empty()) fields[k].set(options, in.values[k]);
}

}  // namespace hooke::cli
