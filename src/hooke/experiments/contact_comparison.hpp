#pragma once
/// A calibrated model against the FEM of its own mesh under the same contact: a rigid tool pressed into the body
/// step by step, quasi-statically, the bottom clamped, and at each depth the force on the tool and the displacement
/// field of both (docs/contact.md, "Against the FEM under the same contact").
#include <hooke/calibrate/calibrated_model.hpp>
#include <hooke/contact/rigid_tool.hpp>
#include <vector>

namespace hooke::experiments {

struct ContactPressOptions {
  contact::Pose start;              ///< the tool's pose before it presses (it should not touch the body yet)
  Vec3 direction = -Vec3::UnitZ();  ///< along which it moves (normalised here)
  double depth = 0.0;               ///< how far it moves from start, m (> 0)
  int steps = 8;                    ///< equal increments (>= 1)
  double contact_distance = 0.0;    ///< the barrier's activation distance, m (0: 1 % of the mean boundary edge)
  material::Law reference = material::Law::kNeoHookean;  ///< the FEM's law
};

struct ContactPressRow {
  double travel = 0.0;              ///< the tool's travel from its start, m
  Vec3 fem_force = Vec3::Zero();    ///< the force the FEM body exerts on the tool, N
  Vec3 model_force = Vec3::Zero();  ///< the model's, N
  double force_error = 0.0;         ///< |F_model - F_fem| / |F_fem| (0 while the FEM force is 0)
  double relative_l2 = 0.0;         ///< ||x_model - x_fem|| / ||x_fem - X|| over all nodes (0 at no deformation)
  int fem_contacts = 0, model_contacts = 0;  ///< nodes within the activation distance
  double smallest_gap = 0.0;                 ///< the smaller of both smallest node-to-tool distances, m (> 0)
};

/// Presses `tool` (sphere or capsule) into `model` (any calibrated model of a tet mesh) and into the FEM of the same
/// mesh, material and density (options.reference), both clamped at their lowest face and with the same contact
/// block (contact::boundary_contact, kappa from E), through options.steps equal increments of options.depth, and
/// compares them at each. solve::press_quasi_statically finds the equilibria (Newton with the stability check).
/// @throws InvalidArgument for a surface model or a non-tet mesh, a depth <= 0, steps < 1, a zero direction;
///   SolverFailure naming the model and depth where either has no stable equilibrium
std::vector<ContactPressRow> compare_under_contact(const calibrate::CalibratedModel& model,
                                                   const contact::RigidTool& tool, const ContactPressOptions& options);

}  // namespace hooke::experiments
