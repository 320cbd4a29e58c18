#pragma once
// Python keywords as settings (src/hooke/core/settings.hpp): values to the text the library's rows parse.
#include <pybind11/pybind11.h>

#include <hooke/core/settings.hpp>
#include <string>
#include <utility>
#include <vector>

namespace hooke::python {

/// The keywords of `options` as (name, text) pairs for settings::apply: True/False as on/off, numbers as their
/// shortest exact text, a sequence of numbers as "x,y,z"; None and "" are left out (not
/// given).
std::vector<std::pair<std::string, std::string>> given_settings(const pybind11::dict& options);

/// `rows` as a list of dicts (name, keyword, type, unit, help, long_help, default, min, max, choices, commands).
pybind11::list describe_settings(const std::vector<settings::Description>& rows);

}  // namespace hooke::python
