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
         const mesh::TetrahedralizeOptions& tetrahedralize) {
        calibrate::ModelOptions o;
        o.method = method;
        o.density = density;
        o.tetrahedralize = tetrahedralize;
        py::gil_scoped_release release;
        return calibrate::calibrate_model(mesh, material, o);
      },
      py::arg("mesh"), py::arg("material"), py::arg("method"), py::arg("density"), py::arg("tetrahedralize"));
}

}  // namespace hooke::python
