// hooke.certify: the certificate a model is shipped with.
#include <pybind11/stl.h>
#include <bindings.hpp>
#include <calibrate/calibrated_model.hpp>
#include <hooke/experiments/certify.hpp>
#include <hooke/experiments/term_law_fit.hpp>

namespace py = pybind11;

namespace hooke::python {

void define_certify(py::module_& m) {
  m.def(
      "certify",
      [](calibrate::CalibratedModel& model, double strain, int layers, const std::vector<std::string>& loads,
         const std::string& law, double strain_range) {
        std::vector<model::LoadKind> kinds;
        for (const auto& name : loads) kinds.push_back(model::load_kind_from_name(name));
        const material::Law reference = material::law_from_name(law);
        if (strain_range < 0.0) throw py::value_error("certify: strain_range must be >= 0");
        std::vector<calibrate::CertificateCase> cases;
        {
          py::gil_scoped_release release;
          cases = strain_range > 0.0 ? experiments::certify_range(model, reference, strain_range, layers, kinds)
                                     : experiments::certify(model, strain, layers, kinds);
        }
        model.certificate = cases;
        py::list l;
        for (const auto& k : cases) l.append(certificate_case(k));
        return l;
      },
      py::arg("model"), py::arg("strain") = 0.01, py::arg("layers") = 4,
      py::arg("loads") = std::vector<std::string>{"stretch", "compress", "shear"}, py::arg("law") = "linear",
      py::arg("strain_range") = 0.0,
      "Stretch, compress and shear (or the `loads` named) at mean linear-FEM strain `strain` against the linear FEM: "
      "per case max / mean node error (m) and relative L2. With strain_range > 0: the same cases under displacement "
      "control at 1 % and at strain_range against the FEM of `law`, each with its force_error. Stored in "
      "model.certificate (written with the model).");
}

}  // namespace hooke::python
