#include <hooke/calibrate/spring_model.hpp>
#include <hooke/model/orientation_guard.hpp>
#include <hooke/springs/spring_block.hpp>
#include <hooke/springs/tet_volume_block.hpp>
#include <hooke/springs/triangle_area_block.hpp>

namespace hooke::calibrate {

void add_spring_terms(model::Model& model, const SpringModel& s) {
  if (!s.pairs.empty())
    model.add(
        std::make_unique<springs::SpringBlock>(model.dim(), s.pairs, s.stiffness, s.rest_length, s.spring_exponent));
  if (s.volume_tets.rows() > 0 && s.volume_tets.cols() == 3)  // area terms of planar triangles (any-nu-triangle)
    model.add(std::make_unique<springs::TriangleAreaBlock>(s.volume_tets, s.volume_stiffness, s.rest_volume,
                                                           s.volume_exponent));
  else if (s.volume_tets.rows() > 0)
    model.add(
        std::make_unique<springs::TetVolumeBlock>(s.volume_tets, s.volume_stiffness, s.rest_volume, s.volume_exponent));
}

std::shared_ptr<model::Model> make_model(const mesh::Mesh& mesh, const SpringModel& s) {
  auto m = std::make_shared<model::Model>(mesh.dim(), Eigen::Map<const VecX>(mesh.nodes.data(), mesh.nodes.size()));
  add_spring_terms(*m, s);
  // Springs alone admit a body turned inside out as an "equilibrium"; like the FEM, never accept one.
  if (mesh.kind != mesh::ElementKind::kSurfaceTriangle && mesh.element_count() > 0)
    m->add(std::make_unique<model::OrientationGuard>(mesh));
  return m;
}

SpringModel springs_part(const SpringModel& springs) {
  SpringModel out = springs;
  out.volume_tets.resize(0, 0);
  out.volume_stiffness.resize(0);
  out.rest_volume.resize(0);
  return out;
}

SpringModel volume_part(const SpringModel& springs) {
  SpringModel out = springs;
  out.pairs.clear();
  out.stiffness.resize(0);
  out.rest_length.resize(0);
  return out;
}

SparseMatrix linearised_stiffness(const mesh::Mesh& mesh, const SpringModel& s) {
  const auto m = make_model(mesh, s);
  return m->hessian(m->rest_positions());
}

}  // namespace hooke::calibrate
