#include <algorithm>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/core/name_table.hpp>
#include <hooke/identify/parameter_layout.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/mesh/topology.hpp>
#include <limits>
#include <map>

namespace hooke::identify {
namespace {
constexpr NameTable<Parameters, 4> kNames{"identification parameters",
                                          {{{Parameters::kSprings, "springs"},
                                            {Parameters::kSpringsVolume, "springs+volume"},
                                            {Parameters::kSpringsVolumeRestLength, "springs+volume+rest-length"},
                                            {Parameters::kScale, "scale"}}}};
}  // namespace

Parameters parameters_from_name(std::string_view name) { return kNames.from_name(name); }
std::string_view parameters_name(Parameters parameters) { return kNames.name(parameters); }

VecX ParameterLayout::lower_bounds() const {
  VecX lower = VecX::Zero(size());
  lower.tail(offset_count()).setConstant(-std::numeric_limits<double>::infinity());
  if (negative_volume)
    lower.segment(spring_count(), volume_count()).setConstant(-std::numeric_limits<double>::infinity());
  return lower;
}

ParameterLayout parameter_layout(const mesh::Mesh& mesh, Parameters parameters) {
  if (mesh.kind != mesh::ElementKind::kTet && mesh.kind != mesh::ElementKind::kTriangle)
    throw InvalidArgument("identification needs a tet or triangle mesh; " + mesh.source + " has " +
                          std::string(mesh::element_kind_name(mesh.kind)) + " elements");
  if (parameters == Parameters::kScale)
    throw InvalidArgument("'scale' has no parameter layout: it scales a start model (identify::fit_scale)");
  if (parameters != Parameters::kSprings && mesh.kind != mesh::ElementKind::kTet)
    throw InvalidArgument("identification parameters '" + std::string(parameters_name(parameters)) +
                          "' need a tet mesh (volume terms); use 'springs' on " + mesh.source);
  ParameterLayout layout;
  layout.parameters = parameters;
  layout.dim = mesh.dim();
  layout.pairs = mesh::unique_edges(mesh);
  layout.rest_length.resize(layout.spring_count());
  for (int s = 0; s < layout.spring_count(); ++s)
    layout.rest_length(s) = (mesh.nodes.row(layout.pairs[s][1]) - mesh.nodes.row(layout.pairs[s][0])).norm();
  if (parameters != Parameters::kSprings) {
    layout.tets = mesh.elements;
    layout.rest_volume.resize(mesh.element_count());
    for (int t = 0; t < mesh.element_count(); ++t) layout.rest_volume(t) = mesh::element_measure(mesh, t);
  }
  return layout;
}

calibrate::SpringModel spring_model(const ParameterLayout& layout, const VecX& theta, int* clamped) {
  const int ns = layout.spring_count(), nt = layout.volume_count();
  calibrate::SpringModel out;
  out.dim = layout.dim;
  out.spring_exponent = layout.spring_exponent;
  out.volume_exponent = layout.volume_exponent;
  out.pairs = layout.pairs;
  out.stiffness = theta.head(ns).cwiseMax(0.0);
  out.rest_length = layout.rest_length;
  int outside = 0;
  if (layout.offset_count()) {
    for (int s = 0; s < ns; ++s) {
      const double k = out.stiffness(s), length = layout.rest_length(s);
      if (!(k > 0.0)) continue;
      const double l0 = length - theta(ns + nt + s) / k;
      if (l0 < 0.5 * length || l0 > 2.0 * length) ++outside;
      out.rest_length(s) = std::clamp(l0, 0.5 * length, 2.0 * length);
    }
  }
  if (nt) {
    out.volume_tets = layout.tets;
    out.volume_stiffness = theta.segment(ns, nt);
    if (!layout.negative_volume) out.volume_stiffness = out.volume_stiffness.cwiseMax(0.0);
    out.rest_volume = layout.rest_volume;
  }
  if (clamped) *clamped = outside;
  return out;
}

VecX parameters_of(const ParameterLayout& layout, const calibrate::SpringModel& springs) {
  VecX theta = VecX::Zero(layout.size());
  std::map<std::array<int, 2>, int> index;
  for (int s = 0; s < layout.spring_count(); ++s) index[layout.pairs[s]] = s;
  for (std::size_t s = 0; s < springs.pairs.size(); ++s) {
    auto pair = springs.pairs[s];
    if (pair[0] > pair[1]) std::swap(pair[0], pair[1]);
    if (const auto it = index.find(pair); it != index.end()) theta(it->second) += springs.stiffness(s);
  }
  if (layout.volume_count()) {
    if (springs.volume_tets.rows() != 0) {
      if (springs.volume_tets != layout.tets)
        throw InvalidArgument("the spring model's volume terms are not on the layout's tets");
      theta.segment(layout.spring_count(), layout.volume_count()) = springs.volume_stiffness;
    }
  }
  return theta;
}

}  // namespace hooke::identify
