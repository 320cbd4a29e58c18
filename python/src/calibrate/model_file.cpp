// hooke.read_model / write_model: model files (.json, and the .vtu / .csv exports).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <bindings.hpp>
#include <hooke/calibrate/model_file.hpp>

namespace py = pybind11;

namespace hooke::python {

using calibrate::CalibratedModel;

void define_model_file(py::module_& m) {
  m.def(
      "read_model",
      [](const std::filesystem::path& path) {
        py::gil_scoped_release release;
        return calibrate::read_model(path);
      },
      py::arg("path"),
      "Reads a model file (.json, schema of docs/model_format.md). Raises ParseError naming the file and the entry.");
  m.def(
      "write_model",
      [](const std::filesystem::path& path, const CalibratedModel& model) {
        calibrate::validate_model(model, path.string());
        calibrate::write_model(path, model);
      },
      py::arg("path"), py::arg("model"),
      "Writes the model as .json, .vtu (springs as lines) or .csv by extension, atomically.");
}

}  // namespace hooke::python
