// The compiled part of the hooke package: the library's API, bound (not the CLI's).
#include <bindings.hpp>
#include <hooke/core/log.hpp>
#include <hooke/core/version.hpp>
#include <hooke/image/label_mesh.hpp>
#include <string>

PYBIND11_MODULE(_hooke, m) {
  m.doc() = "hooke: mass-spring models calibrated from Young's modulus and Poisson's ratio (compiled core)";
  m.attr("__version__") = std::string(hooke::kVersion);
  hooke::image::register_label_image_reader();  // hooke.read_mesh and every mesh argument take label images
  hooke::python::define_error(m);
  hooke::python::define_settings(m);
  hooke::python::define_mesh(m);
  hooke::python::define_material(m);
  hooke::python::define_calibrated_model(m);
  hooke::python::define_model_factory(m);
  hooke::python::define_model_file(m);
  hooke::python::define_compare(m);
  hooke::python::define_certify(m);
  hooke::python::define_reproduce(m);
  hooke::python::define_identify(m);
  hooke::python::define_static_equilibrium(m);
  hooke::python::define_simulator(m);
  hooke::python::define_contact(m);
  hooke::python::define_live_simulation(m);
  // The library's messages go to Python's logging ("hooke" logger; the package installs a NullHandler, so nothing
  // prints unless the application configures logging). Messages may come from threads without the GIL.
  hooke::set_log_sink([](hooke::LogLevel level, std::string_view message) {
    pybind11::gil_scoped_acquire gil;
    static const int levels[] = {10, 20, 30, 40};  // logging.DEBUG, INFO, WARNING, ERROR
    pybind11::module_::import("logging").attr("getLogger")("hooke").attr("log")(levels[static_cast<int>(level)],
                                                                                std::string(message));
  });
}
