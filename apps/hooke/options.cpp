#include <hooke/core/error.hpp>

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

}  // namespace hooke::cli
