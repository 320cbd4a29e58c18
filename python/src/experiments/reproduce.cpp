// hooke.reproduce: a paper's experiments with their report (Markdown, JSON, figure specs) written to a folder; the
// pure-Python layer returns the JSON report as a dict.
#include <pybind11/stl/filesystem.h>
#include <bindings.hpp>
#include <hooke/core/error.hpp>
#include <hooke/experiments/reproduce_arnab2008.hpp>
#include <hooke/experiments/reproduce_lloyd2007.hpp>

namespace py = pybind11;

namespace hooke::python {

void define_reproduce(py::module_& m) {
  m.attr("_default_mesh_dir") = std::string(HOOKE_MESH_DIR);
  m.def(
      "_reproduce",
      [](const std::string& paper, const std::filesystem::path& out_dir, const std::filesystem::path& mesh_dir) {
        py::gil_scoped_release release;
        if (paper == "arnab2008") {
          experiments::write_arnab2008_report(out_dir, experiments::reproduce_arnab2008());
          return;
        }
        if (paper != "lloyd2007")
          throw InvalidArgument("unknown paper '" + paper + "' (available: lloyd2007, arnab2008)");
        experiments::write_lloyd2007_report(out_dir, experiments::reproduce_lloyd2007(mesh_dir));
      },
      py::arg("paper"), py::arg("out_dir"), py::arg("mesh_dir"));
}

}  // namespace hooke::python
