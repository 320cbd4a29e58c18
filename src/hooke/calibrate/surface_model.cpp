#include <cctype>
#include <hooke/calibrate/surface_model.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/log.hpp>
#include <hooke/core/name_table.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/mesh/topology.hpp>
#include <hooke/springs/spring_block.hpp>
#include <map>

namespace hooke::calibrate {

namespace {
constexpr NameTable<SurfaceScheme, 4> kSchemes{
    "surface scheme",
    {{{SurfaceScheme::kA, "A"}, {SurfaceScheme::kB, "B"}, {SurfaceScheme::kC, "C"}, {SurfaceScheme::kD, "D"}}}};
}  // namespace

std::string_view surface_scheme_name(SurfaceScheme scheme) { return kSchemes.name(scheme); }

SurfaceScheme surface_scheme_from_name(std::string_view name) {
  std::string upper(name);
  for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return kSchemes.from_name(upper.size() == 1 ? std::string_view(upper) : name);
}

namespace {

// Membrane springs on the surface edges, Lloyd et al. 2007 Eq. 9: k_ij = sum over the (two) triangles t of
// the edge of E t A_t / l_ij^2 (Eq. 8's sqrt(3)/4 E t scaled by A_t / A_0, A_0 = sqrt(3)/4 l^2).
SpringModel membrane(const mesh::Mesh& m, double youngs_modulus, double thickness) {
  std::map<std::array<int, 2>, double> k;
  for (int t = 0; t < m.element_count(); ++t) {
    const Vec3 a = m.nodes.row(m.elements(t, 0)).transpose(), b = m.nodes.row(m.elements(t, 1)).transpose(),
               c = m.nodes.row(m.elements(t, 2)).transpose();
    const double area = 0.5 * (b - a).cross(c - a).norm();
    for (int e = 0; e < 3; ++e) {
      const int i = m.elements(t, e), j = m.elements(t, (e + 1) % 3);
      const double l2 = (m.nodes.row(i) - m.nodes.row(j)).squaredNorm();
      k[{std::min(i, j), std::max(i, j)}] += youngs_modulus * thickness * area / l2;
    }
  }
  std::vector<std::array<int, 2>> pairs;
  VecX stiffness(static_cast<Eigen::Index>(k.size())), rest(static_cast<Eigen::Index>(k.size()));
  Eigen::Index s = 0;
  for (const auto& [pair, ks] : k) {
    pairs.push_back(pair);
    stiffness(s) = ks;
    rest(s) = (m.nodes.row(pair[0]) - m.nodes.row(pair[1])).norm();
    ++s;
  }
  SpringModel out;
  out.pairs = std::move(pairs);
  out.stiffness = std::move(stiffness);
  out.rest_length = std::move(rest);
  return out;
}

}  // namespace

double default_membrane_thickness(double area, const surface::Discretisation& d) {
  return kMembraneRatio * area / static_cast<double>(d.normal_length.size()) / d.normal_length.mean();
}

SurfaceModel make_surface_model(mesh::Mesh mesh, const material::Material& material, const SurfaceOptions& o) {
  material::validate(material);
  if (material.law != material::Law::kLinear)
    throw InvalidArgument("the surface model is linear: its stiffnesses come from E and nu of a linear law");
  SurfaceModel out;
  out.check = mesh::check_closed_surface(mesh);
  // The radial construction of Fig. 5 where the surface is star-shaped from the centre (always when a centre is
  // given); otherwise the depth reading of Fig. 6 (surface::discretise_by_depth, docs/surface.md).
  const Vec3 centre = o.centre ? *o.centre : mesh::volume_centroid(mesh);
  try {
    surface::require_star_shaped(mesh, centre);
    out.discretisation = surface::discretise(mesh, centre);
  } catch (const InvalidMesh& e) {
    if (o.centre) throw;
    log(LogLevel::kInfo, std::string("surface model: ") + e.what() +
                             "; each node anchored at half the body's depth along its normal instead");
    out.discretisation = surface::discretise_by_depth(mesh);
    out.radial = false;
  }
  const surface::Discretisation& d = out.discretisation;
  const int n = mesh.node_count();
  const double e = material.youngs_modulus, nu = material.poisson_ratio;

  // Masses (Sec. Mass Estimation): the estimation ratio, or uniform for scheme A.
  const double total = o.mass > 0.0 ? o.mass : o.density * d.volume;
  if (!(total > 0.0)) throw InvalidArgument("the object mass must be positive: give a density or a mass (kg)");
  const VecX node_mass =
      o.scheme == SurfaceScheme::kA ? VecX::Constant(n, total / n) : surface::estimated_masses(d, total);
  out.masses.resize(3 * n);
  for (int i = 0; i < n; ++i) out.masses.segment<3>(3 * i).setConstant(node_mass(i));

  // Inner stiffness (Sec. The Estimation of Spring Stiffness): [K_E; K_G]_i = E sum V_t / L'^2 [1; shear],
  // K_B,i = E / (3 (1 - 2 nu)) sum V_t / L'^2, with V_t and L' of Fig. 6 (see Discretisation::normal_length).
  const VecX per_length = d.normal_volume.cwiseQuotient(d.normal_length.cwiseProduct(d.normal_length));
  const double shear =
      o.shear_factor == ShearFactor::kShearModulus ? 1.0 / (2.0 * (1.0 + nu)) : 1.0 / (2.0 * (1.0 - nu));
  const double bulk = e / (3.0 * (1.0 - 2.0 * nu));
  out.k_normal = e * per_length;
  out.k_shear = shear * out.k_normal;
  out.k_bulk = bulk * per_length;
  if (o.scheme == SurfaceScheme::kA || o.scheme == SurfaceScheme::kB) {
    out.k_normal.setConstant(out.k_normal.mean());
    out.k_shear.setConstant(out.k_shear.mean());
    out.k_bulk.setConstant(out.k_bulk.mean());
  }
  const surface::AnchorLaw law =
      o.anchor_law ? *o.anchor_law
                   : (o.scheme == SurfaceScheme::kD ? surface::AnchorLaw::kBlend : surface::AnchorLaw::kSingle);
  const bool penalty = o.volume_penalty ? *o.volume_penalty : o.scheme == SurfaceScheme::kD;

  out.membrane_thickness =
      o.membrane_thickness >= 0.0 ? o.membrane_thickness : default_membrane_thickness(mesh::total_measure(mesh), d);
  VecX rest = Eigen::Map<const VecX>(mesh.nodes.data(), mesh.nodes.size());
  out.model = std::make_shared<model::Model>(3, rest);
  if (out.membrane_thickness > 0.0) {
    out.membrane = membrane(mesh, e, out.membrane_thickness);
    out.model->add(std::make_unique<springs::SpringBlock>(3, out.membrane.pairs, out.membrane.stiffness,
                                                          out.membrane.rest_length));
  }
  out.law = law;
  out.bulk_modulus = bulk;
  auto anchors = std::make_unique<surface::AnchorBlock>(rest, d.normal_cones, out.k_normal, out.k_shear, law);
  out.anchors = anchors.get();
  out.model->add(std::move(anchors));
  if (penalty) {
    auto volume = std::make_unique<surface::VolumePenaltyBlock>(mesh.elements, d.volume, out.k_bulk, d.normal_length,
                                                                bulk, o.volume_force);
    out.volume = volume.get();
    out.model->add(std::move(volume));
  }
  out.mesh = std::move(mesh);
  return out;
}

}  // namespace hooke::calibrate
