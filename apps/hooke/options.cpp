#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/calibrate/model_file.hpp>
#include <hooke/calibrate/model_settings.hpp>
#include <hooke/calibrate/region_materials.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/units.hpp>
#include <hooke/image/label_mesh.hpp>
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

void add_settings(CLI::App* cmd, const std::vector<settings::Description>& rows, GivenSettings& given,
                  const std::string& group) {
  for (const settings::Description& row : rows) {
    const std::string flag = "--" + row.name, name = row.name;
    CLI::Option* option = nullptr;
    if (row.type == settings::Type::kFlag) {
      option = cmd->add_flag_callback(
          flag, [&given, name] { given.emplace_back(name, "on"); }, row.long_help());
    } else {
      option = cmd->add_option_function<std::string>(
          flag, [&given, name](const std::string& text) { given.emplace_back(name, text); }, row.long_help());
      option->type_name(row.type == settings::Type::kNumber    ? "FLOAT"
                        : row.type == settings::Type::kInteger ? "INT"
                                                               : "TEXT");
      if (!row.default_text.empty()) option->default_str(row.default_text);
    }
    if (!group.empty()) option->group(group);
  }
}

void add_model_source_options(CLI::App* cmd, ModelSource& in, unsigned command) {
  cmd->add_option("mesh", in.mesh_path,
                  "Mesh file (.msh, .vtu, .node/.ele, .obj, .off, .stl; a closed surface is tetrahedralized for every "
                  "method but surface), or a model file (.json, as --model); optional with --model");
  cmd->add_option("--model", in.model_path,
                  "Model file (.json, from hooke calibrate or written by hand) instead of "
                  "--method, --young and --poisson");
  cmd->add_option("--young", in.young, "Young's modulus E, Pa");
  cmd->add_option("--poisson", in.poisson, "Poisson's ratio nu, in (-1, 0.5)");
  cmd->add_option("--material", in.materials,
                  "REGION=E,NU (repeatable): E (Pa) and nu of the elements of one region (a mesh's region tag, an "
                  "image's label); --young and --poisson are then those of the regions not listed, and may be left "
                  "out when every region is (docs/regions.md)");
  cmd->add_option("--unit", in.unit, "Length unit of the mesh file (and of printed lengths): m, cm, mm, um")
      ->capture_default_str();
  cmd->add_option("--thickness", in.thickness, "Plate thickness for 2D meshes, m")->capture_default_str();
  cmd->add_option("--plane", in.plane, "2D models: stress or strain")->capture_default_str();
  add_settings(cmd, settings::describe(experiments::calibration_settings(), command), in.given, "Model");
}

experiments::CalibrationSettings calibration_settings(const ModelSource& in) {
  experiments::CalibrationSettings s;
  settings::apply(experiments::calibration_settings(), s, in.given, 0, metres_per_unit(in.unit));
  return s;
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
    if (!std::isnan(in.young) || !std::isnan(in.poisson) || !in.materials.empty())
      throw InvalidArgument("--model carries its material: drop --young, --poisson and --material");
    calibrate::CalibratedModel model = calibrate::read_model(in.model_path);
    if (!in.mesh_path.empty()) calibrate::require_same_nodes(model, io::read_mesh(in.mesh_path, ro));
    return model;
  }
  if (in.mesh_path.empty()) throw InvalidArgument("give a mesh file (or --model MODEL.json)");
  if (in.materials.empty() && (std::isnan(in.young) || std::isnan(in.poisson)))
    throw InvalidArgument("--young and --poisson are required (or --material REGION=E,NU, or --model MODEL.json)");
  // The law is the FEM model's (--method fem); every calibration starts from the linear material.
  calibrate::ModelOptions mo = calibration_settings(in).model;
  for (const std::string& text : in.materials) mo.regions.push_back(calibrate::parse_region_material(text));
  const mesh::Mesh mesh = io::read_mesh(in.mesh_path, ro);
  const auto [young, poisson] = calibrate::unlisted_elasticity(mesh, mo.regions, in.young, in.poisson);
  material::Material mat{mo.method == "fem" ? material::law_from_name(in.law) : material::Law::kLinear, young, poisson,
                         material::plane_from_name(in.plane), in.thickness};
  calibrate::CalibratedModel model = calibrate::calibrate_model(mesh, mat, mo);
  if (!model.meshing.empty()) std::fprintf(stderr, "hooke: tetrahedralized: %s\n", model.meshing.c_str());
  if (!model.choice.empty()) std::fprintf(stderr, "hooke: %s\n", model.choice.c_str());  // what --method auto picked
  return model;
}

int parse_and_run(CLI::App& app, int argc, char** argv, const char* program, const std::function<int()>& action) {
  image::register_label_image_reader();  // every command that reads a mesh takes a label image
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
