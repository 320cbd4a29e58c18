// The compiled part of the hooke package: the library's API, bound (not the CLI's).
#include <bindings.hpp>
#include <hooke/core/version.hpp>

PYBIND11_MODULE(_hooke, m) {
  m.doc() = "hooke: mass-spring models calibrated from Young's modulus and Poisson's ratio (compiled core)";
  m.attr("__version__") = std::string(hooke::kVersion);
  hooke::python::define_error(m);
  hooke::python::define_mesh(m);
  hooke::python::define_material(m);
  hooke::python::define_model(m);
  hooke::python::define_compare(m);
  hooke::python::define_reproduce(m);
  hooke::python::define_static_equilibrium(m);
  hooke::python::define_simulator(m);
}
