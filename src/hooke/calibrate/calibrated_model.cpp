#include <cmath>
#include <hooke/calibrate/calibrated_model.hpp>
#include <hooke/calibrate/method.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/name_table.hpp>
#include <hooke/mesh/reorder.hpp>
#include <hooke/surface/normal_cone.hpp>
#include <string>

namespace hooke::calibrate {

std::vector<material::Material> element_materials(const CalibratedModel& model) {
  return element_materials(model.mesh, model.material, model.regions);
}

namespace {
constexpr NameTable<ModelKind, 4> kKinds{"model kind",
                                         {{{ModelKind::kSprings, "springs"},
                                           {ModelKind::kSurface, "surface"},
                                           {ModelKind::kFem, "fem"},
                                           {ModelKind::kFile, "file"}}}};

// The kind of a model factory name, or nullopt for a name it does not know.
std::optional<ModelKind> kind_of_name(std::string_view method) {
  if (method == "auto") return ModelKind::kSprings;
  for (const std::string_view name : method_names())
    if (name == method) return ModelKind::kSprings;
  for (const auto& [kind, name] : kKinds.entries)
    if (name == method && kind != ModelKind::kSprings) return kind;
  return std::nullopt;
}
}  // namespace

std::string_view model_kind_name(ModelKind kind) { return kKinds.name(kind); }

ModelKind model_kind_of_method(std::string_view method) {
  if (const std::optional<ModelKind> kind = kind_of_name(method)) return *kind;
  std::string all = "auto";
  for (const std::string_view name : method_names()) all += ", " + std::string(name);
  for (const auto& [kind, name] : kKinds.entries)
    if (kind != ModelKind::kSprings) all += ", " + std::string(name);
  throw InvalidArgument("unknown model method '" + std::string(method) + "' (use " + all + ")");
}

ModelKind model_kind(const CalibratedModel& model) {
  if (model.surface) return ModelKind::kSurface;
  return kind_of_name(model.method).value_or(ModelKind::kFile);
}
namespace {

std::string entry(const std::string& what, Eigen::Index i) { return what + "[" + std::to_string(i) + "]"; }

struct Checker {
  const ModelRejection& reject;
  [[noreturn]] void fail(const std::string& where, const std::string& why) const {
    reject(where, why);
    throw InvalidArgument(where + ": " + why);  // a rejection that did not throw
  }
  void node(const std::string& where, int index, int nodes) const {
    if (index < 0 || index >= nodes)
      fail(where, "node index " + std::to_string(index) + " is out of range (the model has " + std::to_string(nodes) +
                      " nodes, numbered from 0)");
  }
  void finite(const std::string& where, double v, const char* what) const {
    if (!std::isfinite(v)) fail(where, std::string(what) + " is not a finite number");
  }
  void positive(const std::string& where, double v, const char* what) const {
    finite(where, v, what);
    if (!(v > 0.0)) fail(where, std::string(what) + " " + std::to_string(v) + " must be > 0");
  }
  void non_negative(const std::string& where, double v, const char* what) const {
    finite(where, v, what);
    if (v < 0.0) fail(where, std::string(what) + " " + std::to_string(v) + " must be >= 0");
  }
  void per_node(const char* what, Eigen::Index size, int nodes) const {
    if (size != nodes)
      fail(what, "has " + std::to_string(size) + " entries, the model has " + std::to_string(nodes) + " nodes");
  }
};

void validate_surface(const SurfaceTerms& s, const Checker& c, int n) {
  c.per_node("surface.anchors", s.k_normal.size(), n);
  if (s.k_shear.size() != n || s.normals.rows() != n || s.normals.cols() != 3 || s.normal_cones.rows() != n ||
      s.normal_cones.cols() != 6)
    c.fail("surface.anchors", "needs K_E, K_G, a normal and a normal cone for each node");
  for (int i = 0; i < n; ++i) {
    const std::string where = entry("surface.anchors", i);
    c.non_negative(where, s.k_normal(i), "K_E");
    c.non_negative(where, s.k_shear(i), "K_G");
    if (!s.normals.row(i).allFinite() || std::abs(s.normals.row(i).norm() - 1.0) > 1e-6)
      c.fail(where, "the normal must be a finite unit vector");
    if (!s.normal_cones.row(i).allFinite()) c.fail(where, "the normal cone must be finite");
    const Vec3 eig = Eigen::SelfAdjointEigenSolver<Mat3>(surface::unpack_cone(s.normal_cones.row(i))).eigenvalues();
    if (eig.minCoeff() < -1e-9 || eig.maxCoeff() > 1.0 + 1e-9)
      c.fail(where, "the normal cone's eigenvalues must lie in [0, 1]");
  }
  for (int a = 0; a < 3; ++a) c.finite("surface.centre", s.centre(a), "the centre");
  if (!s.volume_penalty) return;
  c.positive("surface.volume_penalty.rest_volume", s.rest_volume, "V0");
  c.positive("surface.volume_penalty.bulk_modulus", s.bulk_modulus, "K");
  c.per_node("surface.volume_penalty.nodes", s.k_bulk.size(), n);
  c.per_node("surface.volume_penalty.nodes", s.normal_length.size(), n);
  for (int i = 0; i < n; ++i) {
    const std::string where = entry("surface.volume_penalty.nodes", i);
    c.non_negative(where, s.k_bulk(i), "K_B");
    c.positive(where, s.normal_length(i), "L'");
  }
}

}  // namespace

void validate_model(const CalibratedModel& model, const std::string& source) {
  validate_model(model, [&](const std::string& entry, const std::string& why) {
    throw InvalidArgument(source + ": " + entry + ": " + why);
  });
}

void validate_model(const CalibratedModel& m, const ModelRejection& reject) {
  const Checker c{reject};
  const int n = m.mesh.node_count(), d = m.mesh.dim(), npe = mesh::nodes_per_element(m.mesh.kind);
  if (n == 0) c.fail("nodes", "the model has no nodes");
  if (m.mesh.nodes.cols() != d) c.fail("nodes", "need " + std::to_string(d) + " coordinates each");
  for (int i = 0; i < n; ++i)
    if (!m.mesh.nodes.row(i).allFinite()) c.fail(entry("nodes", i), "a coordinate is not a finite number");
  if (m.mesh.elements.cols() != npe && m.mesh.element_count() > 0)
    c.fail("elements", "need " + std::to_string(npe) + " nodes each");
  for (int e = 0; e < m.mesh.element_count(); ++e)
    for (int k = 0; k < npe; ++k) c.node(entry("elements", e), m.mesh.elements(e, k), n);
  if (m.masses.size() != static_cast<Eigen::Index>(d) * n)
    c.fail("masses", "has " + std::to_string(m.masses.size() / std::max(d, 1)) + " entries, the model has " +
                         std::to_string(n) + " nodes");
  for (int i = 0; i < n; ++i) c.positive(entry("masses", i), m.masses(d * i), "mass");
  if (!m.regions.empty()) {  // each listed region's material in range, listed once, and present in the mesh
    try {
      element_materials(m);
    } catch (const Error& e) {
      c.fail("regions", e.what());
    }
  }
  const SpringModel& s = m.springs;
  // A law's exponent of a few units already changes a term's stiffness at 50 % strain by orders of magnitude.
  for (const auto& [name, q] : {std::pair{"term_law.spring_exponent", s.spring_exponent},
                                std::pair{"term_law.volume_exponent", s.volume_exponent}})
    if (!(q >= -8.0 && q <= 8.0)) c.fail(name, "exponent " + std::to_string(q) + " must be a number in [-8, 8]");
  if (s.stiffness.size() != static_cast<Eigen::Index>(s.pairs.size()) ||
      s.rest_length.size() != static_cast<Eigen::Index>(s.pairs.size()))
    c.fail("springs", "need a stiffness and a rest length each");
  for (size_t k = 0; k < s.pairs.size(); ++k) {
    const std::string where = entry("springs", static_cast<Eigen::Index>(k));
    c.node(where, s.pairs[k][0], n);
    c.node(where, s.pairs[k][1], n);
    if (s.pairs[k][0] == s.pairs[k][1]) c.fail(where, "a spring needs two different nodes");
    c.non_negative(where, s.stiffness(static_cast<Eigen::Index>(k)), "stiffness k");
    c.positive(where, s.rest_length(static_cast<Eigen::Index>(k)), "rest length l0");
  }
  if (s.volume_tets.rows() > 0) {
    if (!(d == 3 && s.volume_tets.cols() == 4) && !(d == 2 && s.volume_tets.cols() == 3))
      c.fail("volume_terms", "volume terms need tets of a 3D model (or area terms, triangles of a 2D one)");
    if (s.volume_stiffness.size() != s.volume_tets.rows() || s.rest_volume.size() != s.volume_tets.rows())
      c.fail("volume_terms", "need k_V and V0 for each tet");
    for (Eigen::Index t = 0; t < s.volume_tets.rows(); ++t) {
      const std::string where = entry("volume_terms", t);
      for (Eigen::Index k = 0; k < s.volume_tets.cols(); ++k) c.node(where, s.volume_tets(t, k), n);
      c.finite(where, s.volume_stiffness(t), "k_V");  // negative below nu = 1/4 (any-nu-tet, docs/methods/any_nu.md)
      c.positive(where, s.rest_volume(t), "V0");
    }
  }
  if (m.surface) {
    if (m.mesh.kind != mesh::ElementKind::kSurfaceTriangle) c.fail("surface", "needs a surface-triangle mesh");
    validate_surface(*m.surface, c, n);
  }
  if (model_kind(m) != ModelKind::kFem && s.pairs.empty() && s.volume_tets.rows() == 0 && !m.surface)
    c.fail("springs", "the model has no springs, volume terms or surface terms");
}

void require_same_nodes(const CalibratedModel& model, const mesh::Mesh& mesh) {
  const std::string names = "the model '" + model.mesh.source + "' and the mesh '" + mesh.source + "'";
  if (model.mesh.node_count() != mesh.node_count() || model.mesh.dim() != mesh.dim())
    throw InvalidArgument(names + " do not match: " + std::to_string(model.mesh.node_count()) + " nodes in " +
                          std::to_string(model.mesh.dim()) + "D against " + std::to_string(mesh.node_count()) +
                          " nodes in " + std::to_string(mesh.dim()) + "D");
  const double size = (mesh.nodes.colwise().maxCoeff() - mesh.nodes.colwise().minCoeff()).norm();
  for (int i = 0; i < mesh.node_count(); ++i)
    if ((model.mesh.nodes.row(i) - mesh.nodes.row(i)).norm() > 1e-9 * size)
      throw InvalidArgument(names + " do not match: node " + std::to_string(i) + " is at a different place");
}

CalibratedModel permute_nodes(const CalibratedModel& model, const std::vector<int>& new_to_old) {
  CalibratedModel out = model;
  out.mesh = mesh::permute_nodes(model.mesh, new_to_old);  // checks the permutation
  const int d = model.mesh.dim(), n = model.mesh.node_count();
  std::vector<int> old_to_new(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) old_to_new[static_cast<size_t>(new_to_old[static_cast<size_t>(k)])] = k;
  for (int k = 0; k < n; ++k)
    out.masses.segment(d * k, d) = model.masses.segment(d * new_to_old[static_cast<size_t>(k)], d);
  for (auto& p : out.springs.pairs) {
    p = {old_to_new[static_cast<size_t>(p[0])], old_to_new[static_cast<size_t>(p[1])]};
    if (p[0] > p[1]) std::swap(p[0], p[1]);
  }
  for (Eigen::Index t = 0; t < out.springs.volume_tets.rows(); ++t)
    for (Eigen::Index k = 0; k < out.springs.volume_tets.cols(); ++k)
      out.springs.volume_tets(t, k) = old_to_new[static_cast<size_t>(out.springs.volume_tets(t, k))];
  if (out.surface) {
    SurfaceTerms& s = *out.surface;
    const SurfaceTerms& o = *model.surface;
    for (int k = 0; k < n; ++k) {
      const int i = new_to_old[static_cast<size_t>(k)];
      s.normals.row(k) = o.normals.row(i);
      s.normal_cones.row(k) = o.normal_cones.row(i);
      s.k_normal(k) = o.k_normal(i);
      s.k_shear(k) = o.k_shear(i);
      if (s.volume_penalty) {
        s.k_bulk(k) = o.k_bulk(i);
        s.normal_length(k) = o.normal_length(i);
      }
    }
  }
  return out;
}

}  // namespace hooke::calibrate
