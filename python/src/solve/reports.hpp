#pragma once
// Python classes of the solvers' reports, shared by the static and dynamic bindings.
#include <pybind11/pybind11.h>

#include <hooke/solve/static_equilibrium.hpp>

namespace hooke::python {

void define_reports(pybind11::module_& m);
// Raises hooke.SolverFailure with `report` attached (.report) unless it converged.
void raise_unless_converged(const solve::SolveReport& report);

}  // namespace hooke::python
