#pragma once
/// The integrator's settings by name, whoever sets them: `hooke simulate` and `hooke view` take each as --NAME, the
/// viewer's scripts as `set NAME VALUE`, Python's Simulator and LiveSimulation as NAME=VALUE (dashes as
/// underscores). Adding a field to SimulatorOptions and a row to simulator_fields() is all a new setting needs.
#include <hooke/solve/simulator.hpp>
#include <span>
#include <string>
#include <string_view>

namespace hooke::solve {

/// One user-settable field of SimulatorOptions.
struct SimulatorField {
  std::string_view name;  ///< "integrator", "qn-iterations", "cg-tolerance", ...
  std::string_view help;  ///< one line, with the unit or the names it takes
  /// Sets the field from its text (a name, an integer or a finite number). Ranges are the simulator's to check
  /// (Simulator's constructor). @throws InvalidArgument for text that does not parse
  void (*set)(SimulatorOptions& options, std::string_view text);
  /// The field's value as text that set() takes back.
  std::string (*get)(const SimulatorOptions& options);
};

/// Every user-settable field of SimulatorOptions, in the order --help lists them.
std::span<const SimulatorField> simulator_fields();

/// Sets the field of `options` named `name` from `text`. @return false when no field has that name.
/// @throws InvalidArgument for a malformed value
bool set_simulator_field(SimulatorOptions& options, std::string_view name, std::string_view text);

/// `text` as an integer for setting `name`. @throws InvalidArgument ("set NAME: 'TEXT' is not an integer")
int setting_integer(std::string_view name, std::string_view text);

}  // namespace hooke::solve
