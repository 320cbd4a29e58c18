#pragma once
// One define_<concept>(module) per binding file (python/src mirrors src/hooke, docs/architecture.md), called from
// bindings.cpp.
#include <pybind11/pybind11.h>

namespace hooke::python {

void define_error(pybind11::module_& m);
void define_settings(pybind11::module_& m);
void define_mesh(pybind11::module_& m);
void define_material(pybind11::module_& m);
void define_calibrated_model(pybind11::module_& m);
void define_model_factory(pybind11::module_& m);
void define_model_file(pybind11::module_& m);
void define_compare(pybind11::module_& m);
void define_certify(pybind11::module_& m);
void define_reproduce(pybind11::module_& m);
void define_identify(pybind11::module_& m);
void define_static_equilibrium(pybind11::module_& m);
void define_simulator(pybind11::module_& m);
void define_contact(pybind11::module_& m);
void define_live_simulation(pybind11::module_& m);

}  // namespace hooke::python
