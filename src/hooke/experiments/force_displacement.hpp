#pragma once
/// Force-displacement curves of a spring model (Lloyd et al. 2007, Fig. 1 and Sec. 3.1): an element clamped
/// at its bottom, loaded at its top, stretched and compressed. The spring model is stiffer in stretch than
/// in compression; the linear FEM is not.
#include <hooke/calibrate/method.hpp>
#include <string>
#include <vector>

namespace hooke::experiments {

struct ForceDisplacement {
  std::vector<double> force;                ///< force on each top node along +y, N (negative compresses)
  std::vector<double> spring_displacement;  ///< spring model: mean y displacement of the top nodes, m (NaN if unsolved)
  std::vector<double> fem_displacement;     ///< linear FEM, same force: mean y displacement of the top nodes, m
  std::vector<std::string> status;          ///< spring-model solve status per force
  double stretch_stiffness = 0.0;           ///< least-squares slope F/u through the origin over the F > 0 points, N/m
  double compress_stiffness = 0.0;          ///< the same over the F < 0 points, N/m
  double fem_stiffness = 0.0;               ///< F/u of the linear FEM, N/m
};

/// Clamps the nodes at minimum y, applies `force` along y to every node at maximum y, and solves the spring
/// model of `method` (Newton with load stepping and the stability check) and the linear FEM for each force.
/// @param mesh      a planar mesh of a single element or more, m
/// @param material  plane-stress material (E in Pa, thickness in m)
/// @param forces    forces per top node, N
ForceDisplacement force_displacement(const mesh::Mesh& mesh, const material::Material& material,
                                     calibrate::Method method, const std::vector<double>& forces);

}  // namespace hooke::experiments
