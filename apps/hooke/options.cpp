#include "commands.hpp"

namespace hooke::cli {

void add_model_input_options(CLI::App* cmd, ModelInput& in) {
  cmd->add_option("mesh", in.mesh_path, "Mesh file (.msh, .vtu, .node/.ele, .obj, .off, .stl)")->required();
  cmd->add_option("--young", in.young, "Young's modulus E, Pa")->required();
  cmd->add_option("--poisson", in.poisson, "Poisson's ratio nu, in (-1, 0.5)")->required();
  cmd->add_option("--unit", in.unit, "Length unit of the mesh file (and of printed lengths): m, cm, mm, um")
      ->capture_default_str();
  cmd->add_option("--thickness", in.thickness, "Plate thickness for 2D meshes, m")->capture_default_str();
}

}  // namespace hooke::cli
