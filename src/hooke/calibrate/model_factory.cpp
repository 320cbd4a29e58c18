#include <algorithm>
#include <cmath>
#include <hooke/calibrate/method.hpp>
#include <hooke/calibrate/method_choice.hpp>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/log.hpp>
#include <hooke/fem/elastic_block.hpp>
#include <hooke/io/mesher.hpp>
#include <hooke/model/mass.hpp>
#include <hooke/model/orientation_guard.hpp>

namespace hooke::calibrate {
namespace {

CalibratedModel surface_model(const mesh::Mesh& mesh, const material::Material& material, const ModelOptions& o) {
  SurfaceOptions so = o.surface;
  so.density = o.density;
  const SurfaceModel s = make_surface_model(mesh, material, so);
  CalibratedModel out;
  out.mesh = s.mesh;
  out.masses = s.masses;
  out.springs = s.membrane;
  SurfaceTerms t;
  t.scheme = std::string(surface_scheme_name(so.scheme));
  t.centre = s.discretisation.centre;
  t.anchor_law = s.law;
  t.normals = s.discretisation.normals;
  t.normal_cones = s.discretisation.normal_cones;
  t.k_normal = s.k_normal;
  t.k_shear = s.k_shear;
  t.volume_penalty = s.volume != nullptr;
  t.volume_force = so.volume_force;
  t.rest_volume = s.discretisation.volume;
  t.bulk_modulus = s.bulk_modulus;
  if (t.volume_penalty) {
    t.k_bulk = s.k_bulk;
    t.normal_length = s.discretisation.normal_length;
  }
  out.surface = std::move(t);
  return out;
}

}  // namespace

std::vector<std::string> model_method_names() {
  std::vector<std::string> out{"auto"};
  for (const std::string_view name : method_names()) out.emplace_back(name);
  for (const ModelKind kind : {ModelKind::kSurface, ModelKind::kFem}) out.emplace_back(model_kind_name(kind));
  return out;
}

std::string method_equation(std::string_view method) {
  if (method == "auto") return "the method of smallest measured error for the mesh's element kind and nu";
  switch (model_kind_of_method(method)) {  // throws for an unknown name, listing the names
    case ModelKind::kSurface:
      return "Arnab & Raja: anchors (Eq. 2), volume penalty (Eq. 3, 4), membrane springs of Lloyd et al. Eq. 9";
    case ModelKind::kFem: return "finite elements (CST, Q4, tet4) of the material's law";
    case ModelKind::kSprings:
    case ModelKind::kFile: break;
  }
  return std::string(calibrate::method_equation(method_from_name(method)));  // throws, listing the methods
}

CalibratedModel calibrate_model(const mesh::Mesh& mesh, const material::Material& material,
                                const ModelOptions& options) {
  const std::vector<std::string> names = model_method_names();
  if (std::find(names.begin(), names.end(), options.method) == names.end()) {
    std::string all;
    for (const auto& n : names) all += (all.empty() ? "" : ", ") + n;
    throw InvalidArgument("unknown model method '" + options.method + "' (use " + all + ")");
  }
  material::validate(material);
  if (!(options.density > 0.0) || !std::isfinite(options.density))
    throw InvalidArgument("the density must be a positive number of kg/m^3");
  const ModelKind kind = model_kind_of_method(options.method);
  if (kind == ModelKind::kSurface && !options.regions.empty())
    throw InvalidArgument("the surface model has one material for the whole body: drop --material REGION=E,NU");
  if (mesh.kind == mesh::ElementKind::kSurfaceTriangle && kind != ModelKind::kSurface) {
    mesh::TetrahedralizeReport report;
    const mesh::Mesh tets = io::tetrahedralize(mesh, options.tetrahedralize, &report);
    CalibratedModel out = calibrate_model(tets, material, options);
    out.meshing = report.summary();
    return out;
  }
  const std::vector<material::Material> materials = element_materials(mesh, material, options.regions);
  if (options.method == "auto") {
    material::Material hardest = materials.front();  // the largest nu of the body's materials
    for (const material::Material& m : materials)
      if (m.poisson_ratio > hardest.poisson_ratio) hardest = m;
    const MethodChoice choice = choose_method(mesh.kind, hardest);
    log(LogLevel::kInfo, choice.reason);
    ModelOptions chosen = options;
    chosen.method = choice.method;
    CalibratedModel out = calibrate_model(mesh, material, chosen);
    out.choice = choice.reason;
    return out;
  }
  CalibratedModel out;
  if (kind == ModelKind::kSurface) {
    out = surface_model(mesh, material, options);
  } else {
    out.mesh = mesh;
    if (kind == ModelKind::kSprings) {
      const Method method = method_from_name(options.method);
      out.warnings = validity_warnings(mesh, materials, method);
      out.springs = calibrate(mesh, materials, method);
      out.springs.spring_exponent = options.spring_exponent;
      out.springs.volume_exponent = options.volume_exponent;
    }
    out.masses = model::lumped_masses(mesh, options.density, material.thickness);
  }
  out.method = options.method;
  out.equation = method_equation(options.method);
  out.material = material;
  out.regions = options.regions;
  out.density = options.density;
  return out;
}

BuiltModel build_model(const CalibratedModel& m) {
  validate_model(m, m.mesh.source.empty() ? std::string("the model") : m.mesh.source);
  const int d = m.mesh.dim();
  BuiltModel out;
  out.model = std::make_shared<model::Model>(d, Eigen::Map<const VecX>(m.mesh.nodes.data(), m.mesh.nodes.size()));
  if (model_kind(m) == ModelKind::kFem) {
    out.model = fem::elastic_model(m.mesh, element_materials(m));
    return out;
  }
  add_spring_terms(*out.model, m.springs);
  if (m.surface) {
    const SurfaceTerms& t = *m.surface;
    out.model->add(std::make_unique<surface::AnchorBlock>(out.model->rest_positions(), t.normal_cones, t.k_normal,
                                                          t.k_shear, t.anchor_law));
    if (t.volume_penalty) {
      auto volume = std::make_unique<surface::VolumePenaltyBlock>(m.mesh.elements, t.rest_volume, t.k_bulk,
                                                                  t.normal_length, t.bulk_modulus, t.volume_force);
      out.volume_penalty = volume.get();
      out.model->add(std::move(volume));
    }
  } else if (m.mesh.kind != mesh::ElementKind::kSurfaceTriangle && m.mesh.element_count() > 0) {
    // Springs alone admit a body turned inside out as an "equilibrium"; like the FEM, never accept one.
    out.model->add(std::make_unique<model::OrientationGuard>(m.mesh));
  }
  return out;
}

}  // namespace hooke::calibrate
