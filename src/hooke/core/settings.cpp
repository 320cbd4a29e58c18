#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <hooke/core/error.hpp>
#include <hooke/core/settings.hpp>

namespace hooke::settings {
namespace {

const std::pair<Command, std::string_view> kCommands[] = {
    {kCalibrate, "calibrate"}, {kCompare, "compare"}, {kSimulate, "simulate"}, {kView, "view"},
    {kBatch, "batch"},         {kMesh, "mesh"},       {kBench, "bench"},
};

std::string quoted(std::string_view name) { return name.empty() ? std::string("value") : std::string(name); }

// "[min, max]", or "(min, max]" for an exclusive minimum.
std::string range_text(const Description& row) {
  std::string out(row.exclusive_min ? "(" : "[");
  out += std::isinf(row.min) ? std::string("-inf") : number_text(row.min);
  out += ", ";
  out += std::isinf(row.max) ? std::string("inf") : number_text(row.max);
  out += "]";
  return out;
}

}  // namespace

std::string_view type_name(Type type) {
  switch (type) {
    case Type::kNumber: return "number";
    case Type::kInteger: return "integer";
    case Type::kFlag: return "flag";
    case Type::kChoice: return "choice";
    case Type::kText: return "text";
  }
  return "unknown";
}

std::span<const std::pair<Command, std::string_view>> command_names() { return kCommands; }

double parse_number(std::string_view name, std::string_view text) {
  double v = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v))
    throw InvalidArgument(quoted(name) + ": '" + std::string(text) + "' is not a finite number");
  return v;
}

int parse_integer(std::string_view name, std::string_view text) {
  int v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size())
    throw InvalidArgument(quoted(name) + ": '" + std::string(text) + "' is not an integer");
  return v;
}

bool parse_flag(std::string_view name, std::string_view text) {
  if (text == "on" || text == "true" || text == "1") return true;
  if (text == "off" || text == "false" || text == "0") return false;
  throw InvalidArgument(quoted(name) + " takes on or off, not '" + std::string(text) + "'");
}

std::string number_text(double value) {
  char buffer[32];
  for (int digits = 6; digits <= 17; ++digits) {  // the shortest %g text that reads back exactly
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
    if (std::strtod(buffer, nullptr) == value) break;
  }
  return buffer;
}

void check_range(const Description& row, double value) {
  if ((row.exclusive_min ? value > row.min : value >= row.min) && value <= row.max) return;
  throw InvalidArgument(row.name + " must be in " + range_text(row) + (row.unit.empty() ? "" : " " + row.unit) +
                        ", not " + number_text(value));
}

std::string canonical_name(std::string_view name) {
  std::string out(name);
  std::replace(out.begin(), out.end(), '_', '-');
  return out;
}

std::string Description::keyword() const {
  std::string out = name;
  std::replace(out.begin(), out.end(), '-', '_');
  return out;
}

std::string Description::long_help() const {
  std::string out = help;
  if (!unit.empty())
    out += " (" + unit + (length_power != 0 ? "; on the command line, the mesh file's unit" : "") + ")";
  if (type == Type::kChoice && !choices.empty()) {
    out += "; one of ";
    for (size_t k = 0; k < choices.size(); ++k) out += (k ? ", " : "") + choices[k];
  }
  if ((type == Type::kNumber || type == Type::kInteger) && (!std::isinf(min) || !std::isinf(max)))
    out += "; in " + range_text(*this);
  return out;
}

std::string checked_text(const Description& row, std::string_view text, double metres_per_unit) {
  switch (row.type) {
    case Type::kNumber: {
      double v = parse_number(row.name, text);
      if (row.length_power != 0) v *= std::pow(metres_per_unit, row.length_power);
      check_range(row, v);
      return number_text(v);
    }
    case Type::kInteger: check_range(row, parse_integer(row.name, text)); return std::string(text);
    case Type::kFlag: return parse_flag(row.name, text) ? "on" : "off";
    case Type::kChoice:
      if (!row.choices.empty() && std::find(row.choices.begin(), row.choices.end(), text) == row.choices.end()) {
        std::string valid;
        for (const auto& c : row.choices) valid += (valid.empty() ? "" : ", ") + c;
        throw InvalidArgument("unknown " + row.name + " '" + std::string(text) + "' (use " + valid + ")");
      }
      return std::string(text);
    case Type::kText: return std::string(text);
  }
  return std::string(text);
}

void throw_unknown(std::string_view name, const std::vector<Description>& known) {
  std::string list;
  for (const Description& d : known) list += (list.empty() ? "" : ", ") + d.name;
  throw InvalidArgument("unknown setting '" + std::string(name) + "' (known: " + list + ")");
}

}  // namespace hooke::settings
