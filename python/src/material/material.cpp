// hooke.Material: a linear-elastic (or StVK / Neo-Hookean, for the FEM model) material in SI units.
#include <bindings.hpp>
#include <cmath>
#include <hooke/material/material.hpp>
#include <limits>

namespace py = pybind11;

namespace hooke::python {

void define_material(py::module_& m) {
  py::class_<material::Material>(m, "Material", "E (Pa), nu, the law, and a thickness (m) for 2D meshes.")
      .def(py::init([](double young, double poisson, const py::object& thickness, const std::string& law,
                       const std::string& plane) {
             material::Material mat{material::law_from_name(law), young, poisson, material::plane_from_name(plane),
                                    thickness.is_none() ? 1.0 : thickness.cast<double>()};
             material::validate(mat);
             return mat;
           }),
           py::arg("E"), py::arg("nu"), py::arg("thickness") = py::none(), py::arg("law") = "linear",
           py::arg("plane") = "stress",
           "Material(E, nu, thickness=None, law='linear', plane='stress'): Young's modulus E in Pa (> 0), Poisson's "
           "ratio nu in (-1, 0.5), plate thickness in m for 2D meshes (default 1), law 'linear', 'stvk' or "
           "'neohookean' (used by the 'fem' model), the 2D reduction 'stress' or 'strain'. Raises InvalidMaterial "
           "out of range.")
      .def_readonly("E", &material::Material::youngs_modulus, "Young's modulus, Pa")
      .def_readonly("nu", &material::Material::poisson_ratio, "Poisson's ratio")
      .def_readonly("thickness", &material::Material::thickness, "plate thickness of 2D meshes, m")
      .def_property_readonly(
          "plane", [](const material::Material& mat) { return std::string(material::plane_name(mat.plane)); },
          "'stress' or 'strain' (2D meshes)")
      .def_property_readonly(
          "law", [](const material::Material& mat) { return std::string(material::law_name(mat.law)); },
          "'linear', 'stvk' or 'neohookean'")
      .def("__repr__", [](const material::Material& mat) {
        return "<hooke.Material E=" + std::to_string(mat.youngs_modulus) +
               " Pa, nu=" + std::to_string(mat.poisson_ratio) + ", " + std::string(material::law_name(mat.law)) + ">";
      });
}

}  // namespace hooke::python
