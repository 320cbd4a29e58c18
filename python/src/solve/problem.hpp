#pragma once
// What a Python hooke.Problem holds: the calibrated model (for load cases and masses), its built term blocks and
// the solver's problem.
#include <pybind11/numpy.h>
#include <contact/tool.hpp>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/model/load_case.hpp>
#include <hooke/model/problem.hpp>

namespace hooke::python {

struct ProblemData {
  calibrate::CalibratedModel model;
  model::Problem problem;

  explicit ProblemData(const calibrate::CalibratedModel& m)
      : model(m), problem(model::make_problem(calibrate::build_model(m).model)) {
    problem.external_force = VecX::Zero(problem.model->dof_count());
  }
  void fix_nodes(const std::vector<int>& nodes);
  // The load case `kind` at `traction` (Pa) or, when strain > 0, at the traction giving that mean linear-FEM strain.
  void apply_load(model::LoadKind kind, double traction, double strain);
  // A rigid tool (contact::parse_tool text) at `pose` against the body's boundary (contact::boundary_contact with
  // activation `distance`, 0: automatic). The problem's model is rebuilt with every tool's contact block: simulators
  // and solves made before keep the model they had. `friction` (slip 0: 1e-5 of the bounding-box diagonal) is the
  // contact's Coulomb friction (contact::ContactBlock::set_friction).
  PyTool add_tool(const std::string& shape, const contact::Pose& pose, double distance, contact::Friction friction);
  std::vector<std::shared_ptr<const contact::ContactBlock>> contacts;  ///< one per tool, in the order added
  // Flat positions as an (N, dim) array (a copy).
  pybind11::array_t<double> rows(const VecX& flat) const;
};

}  // namespace hooke::python
