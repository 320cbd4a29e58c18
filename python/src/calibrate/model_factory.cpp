// hooke.calibrate / methods / method_equation: a model from a mesh and a material by method name.
#include <pybind11/stl.h>
#include <bindings.hpp>
#include <hooke/calibrate/model_factory.hpp>

namespace py = pybind11;

namespace hooke::python {

void define_model_factory(py::module_& m) {
  m.def("methods", &calibrate::model_method_names,
        "The stable names calibrate() accepts: the calibration methods, then 'surface' and 'fem'.");
  m.def("method_equation", &calibrate::method_equation, py::arg("method"),
        "Where the constants of `method` come from (paper and equation).");
  m.def(
      "_calibrate",
      [](const mesh::Mesh& mesh, const material::Material& material, const std::string& method, double density,
         const mesh::TetrahedralizeOptions& tetrahedralize, double spring_exponent, double volume_exponent) {
        calibrate::ModelOptions o;
        o.method = method;
        o.density = density;
        o.tetrahedralize = tetrahedralize;
        o.spring_exponent = spring_exponent;
        o.volume_exponent = volume_exponent;
        py::gil_scoped_release release;
        return calibrate::calibrate_model(mesh, material, o);
      },
      py::arg("mesh"), py::arg("material"), py::arg("method"), py::arg("density"), py::arg("tetrahedralize"),
      py::arg("spring_exponent") = 1.0, py::arg("volume_exponent") = 1.0);
}

}  // namespace hooke::python
