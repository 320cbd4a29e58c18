// hooke._settings(command): the declared settings of a command, from which hooke.calibrate's and
// hooke.tetrahedralize's keywords and docstrings and the batch table's columns are made.
#include <pybind11/stl.h>
#include <bindings.hpp>
#include <core/settings.hpp>
#include <hooke/calibrate/model_settings.hpp>
#include <hooke/core/error.hpp>
#include <hooke/experiments/calibration.hpp>

namespace py = pybind11;

namespace hooke::python {
namespace {

std::string setting_text(const std::string& name, const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "on" : "off";
  if (py::isinstance<py::int_>(value)) return py::str(value);
  if (py::isinstance<py::float_>(value)) return settings::number_text(value.cast<double>());
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::sequence>(value) || py::hasattr(value, "__len__")) {
    std::string out;
    for (const py::handle item : value) out += (out.empty() ? "" : ",") + setting_text(name, item);
    return out;
  }
  throw InvalidArgument(name + ": a " + std::string(py::str(value.get_type().attr("__name__"))) +
                        " is not a value of this setting");
}

}  // namespace

std::vector<std::pair<std::string, std::string>> given_settings(const py::dict& options) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& [key, value] : options) {
    if (value.is_none() || (py::isinstance<py::str>(value) && value.cast<std::string>().empty())) continue;
    const std::string name = py::str(key);
    out.emplace_back(name, setting_text(name, value));
  }
  return out;
}

py::list describe_settings(const std::vector<settings::Description>& rows) {
  py::list out;
  for (const settings::Description& d : rows) {
    py::dict r;
    r["name"] = d.name;
    r["keyword"] = d.keyword();
    r["type"] = std::string(settings::type_name(d.type));
    r["unit"] = d.unit;
    r["help"] = d.help;
    r["long_help"] = d.long_help();
    r["default"] = d.default_text;
    r["min"] = d.min;
    r["max"] = d.max;
    r["choices"] = d.choices;
    py::list commands;
    for (const auto& [bit, name] : settings::command_names())
      if (d.commands & bit) commands.append(std::string(name));
    r["commands"] = commands;
    out.append(r);
  }
  return out;
}

void define_settings(py::module_& m) {
  m.def(
      "_settings",
      [](const std::string& command) {
        for (const auto& [bit, name] : settings::command_names())
          if (name == command)
            return describe_settings(bit == settings::kMesh || bit == settings::kView || bit == settings::kBench
                                         ? settings::describe(calibrate::model_settings(), bit)
                                         : settings::describe(experiments::calibration_settings(), bit));
        throw InvalidArgument("unknown command '" + command + "'");
      },
      py::arg("command"),
      "The declared settings of `command` (calibrate, compare, simulate, view, batch, mesh, bench): a list of dicts "
      "(name, keyword, type, unit, help, long_help, default, min, max, choices, commands).");
}

}  // namespace hooke::python
