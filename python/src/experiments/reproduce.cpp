// hooke.reproduce: a paper's experiments with their report (Markdown, JSON, figure specs) written to a folder; the
// pure-Python layer returns the JSON report as a dict.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <bindings.hpp>
#include <hooke/core/error.hpp>
#include <hooke/experiments/nu_range.hpp>
#include <hooke/experiments/reproduce_arnab2008.hpp>
#include <hooke/experiments/reproduce_lloyd2007.hpp>

namespace py = pybind11;

namespace hooke::python {

void define_reproduce(py::module_& m) {
  m.attr("_default_mesh_dir") = std::string(HOOKE_MESH_DIR);
  m.def(
      "_reproduce",
      [](const std::string& paper, const std::filesystem::path& out_dir, const std::filesystem::path& mesh_dir,
         const std::string& nu_range_options) {
        py::gil_scoped_release release;
        if (paper == "nu-range") {
          experiments::write_nu_range_report(
              out_dir,
              experiments::reproduce_nu_range(
                  mesh_dir, nu_range_options.empty() ? experiments::NuRangeOptions{}
                                                     : experiments::nu_range_options_from_json(nu_range_options)));
          return;
        }
        if (paper == "arnab2008") {
          experiments::write_arnab2008_report(out_dir, experiments::reproduce_arnab2008());
          return;
        }
        if (paper != "lloyd2007")
          throw InvalidArgument("unknown paper '" + paper + "' (available: lloyd2007, arnab2008, nu-range)");
        experiments::write_lloyd2007_report(out_dir, experiments::reproduce_lloyd2007(mesh_dir));
      },
      py::arg("paper"), py::arg("out_dir"), py::arg("mesh_dir"), py::arg("nu_range_options") = "");
  // The nu-range study as independent tasks (hooke.batch): options, tasks and rows travel as JSON text.
  m.def("_nu_range_default_options", [] { return experiments::nu_range_options_json({}); });
  m.def(
      "_nu_range_tasks",
      [](const std::filesystem::path& mesh_dir, const std::string& options) {
        std::vector<std::string> out;
        for (const auto& t : experiments::nu_range_tasks(mesh_dir, experiments::nu_range_options_from_json(options)))
          out.push_back(experiments::nu_range_task_json(t));
        return out;
      },
      py::arg("mesh_dir"), py::arg("options"));
  m.def(
      "_nu_range_task",
      [](const std::filesystem::path& mesh_dir, const std::string& options, const std::string& task) {
        const auto o = experiments::nu_range_options_from_json(options);
        const auto t = experiments::nu_range_task_from_json(task);
        py::gil_scoped_release release;
        return experiments::nu_range_rows_json(experiments::run_nu_range_task(mesh_dir, o, t));
      },
      py::arg("mesh_dir"), py::arg("options"), py::arg("task"));
  m.def(
      "_nu_range_write",
      [](const std::filesystem::path& out_dir, const std::string& options, const std::string& rows, double seconds) {
        const auto report = experiments::nu_range_report(experiments::nu_range_options_from_json(options),
                                                         experiments::nu_range_rows_from_json(rows), seconds);
        py::gil_scoped_release release;
        experiments::write_nu_range_report(out_dir, report);
        return report.recommendations;
      },
      py::arg("out_dir"), py::arg("options"), py::arg("rows"), py::arg("seconds"));
}

}  // namespace hooke::python
