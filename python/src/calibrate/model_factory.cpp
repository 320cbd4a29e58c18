// hooke.calibrate / methods / method_equation: a model from a mesh, a material and the calibration settings.
#include <pybind11/stl.h>
#include <bindings.hpp>
#include <core/settings.hpp>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/experiments/calibration.hpp>
#include <tuple>
#include <vector>

namespace py = pybind11;

namespace hooke::python {

void define_model_factory(py::module_& m) {
  m.def("methods", &calibrate::model_method_names,
        "The stable names calibrate() accepts: the calibration methods, then 'surface' and 'fem'.");
  m.def("method_equation", &calibrate::method_equation, py::arg("method"),
        "Where the constants of `method` come from (paper and equation).");
  m.def(
      "_calibrate",
      [](const mesh::Mesh& mesh, const material::Material& material, const py::dict& options,
         const std::vector<std::tuple<int, double, double>>& regions) {
        experiments::CalibrationSettings s;
        settings::apply(experiments::calibration_settings(), s, given_settings(options), settings::kCalibrate);
        for (const auto& [region, young, poisson] : regions) s.model.regions.push_back({region, young, poisson});
        py::gil_scoped_release release;
        return experiments::calibrate_with(mesh, material, s);
      },
      py::arg("mesh"), py::arg("material"), py::arg("options"), py::arg("regions"),
      "hooke.calibrate's core: `options` maps setting names (hooke._settings('calibrate')) to values; `regions` "
      "lists (region, E, nu).");
}

}  // namespace hooke::python
