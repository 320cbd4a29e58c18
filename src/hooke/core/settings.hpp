#pragma once
/// Settings declared once. Each user-settable option of a library struct is a row beside that struct: its name, type,
/// unit, range, help text and the commands that take it, with how it is read from and written to the struct. The
/// front ends generate their options from the rows: `hooke CMD --NAME`, Python keywords NAME (dashes as
/// underscores), the batch table's columns, the viewer's panel and its scripts' `set NAME VALUE`. Parsing and range
/// checks happen here, once, for all of them (docs/architecture.md, "Settings").
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hooke::settings {

enum class Type { kNumber, kInteger, kFlag, kChoice, kText };
/// "number", "integer", "flag", "choice", "text".
std::string_view type_name(Type type);

/// The commands a setting belongs to: a row's `commands` is a set of these bits. Each front end of a command
/// (the CLI sub-command, its Python function, the viewer, the batch table) exposes every row that names it.
enum Command : unsigned {
  kCalibrate = 1u << 0,  ///< hooke calibrate, hooke.calibrate
  kCompare = 1u << 1,    ///< hooke compare
  kSimulate = 1u << 2,   ///< hooke simulate
  kView = 1u << 3,       ///< hooke view, its panel and its scripts' set
  kBatch = 1u << 4,      ///< hooke batch and hooke.batch: a study table's columns
  kMesh = 1u << 5,       ///< hooke mesh tetrahedralize, hooke.tetrahedralize
  kBench = 1u << 6,      ///< hooke bench
};
/// Every command bit with its name ("calibrate", "compare", ...), in the order of Command.
std::span<const std::pair<Command, std::string_view>> command_names();

inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

/// One setting of a struct T.
template <class T>
struct Setting {
  std::string name;  ///< "density", "spring-exponent": --NAME, Python NAME with '-' as '_'
  Type type = Type::kNumber;
  std::string unit;  ///< "kg/m^3", "m", ...; empty for a pure number, a name or a flag
  std::string help;  ///< one or two sentences, without the unit, range or default (generated)
  unsigned commands = 0;
  double min = -kUnbounded, max = kUnbounded;  ///< range of a number or integer, inclusive
  bool exclusive_min = false;                  ///< the value must be above `min`, not equal to it
  /// A length (1) or volume (3): on the command line it is given in the mesh file's unit and converted to metres.
  int length_power = 0;
  std::function<std::vector<std::string>()> choices;  ///< a choice's names
  /// Sets the field from text already parsed and range-checked by settings::set.
  std::function<void(T&, std::string_view)> set;
  /// The field as text that `set` takes back (empty: not set, e.g. an optional left to its default).
  std::function<std::string(const T&)> get;
};

/// A setting as front ends see it, independent of the struct it fills.
struct Description {
  std::string name, unit, help;
  Type type = Type::kNumber;
  unsigned commands = 0;
  double min = -kUnbounded, max = kUnbounded;
  bool exclusive_min = false;
  int length_power = 0;
  std::vector<std::string> choices;
  std::string default_text;  ///< the value of a default-constructed struct, as text (empty: not set)

  /// `help` with the unit, range and choices appended, for --help and docstrings.
  std::string long_help() const;
  /// `name` with dashes as underscores: the Python keyword and the batch column.
  std::string keyword() const;
};

// Parsing, shared by every table (the error names the setting and the text).
/// @throws InvalidArgument ("NAME: 'TEXT' is not a finite number")
double parse_number(std::string_view name, std::string_view text);
/// @throws InvalidArgument ("NAME: 'TEXT' is not an integer")
int parse_integer(std::string_view name, std::string_view text);
/// "on", "true", "1" or "off", "false", "0". @throws InvalidArgument naming the setting
bool parse_flag(std::string_view name, std::string_view text);
/// A number as the shortest text that parses back to it.
std::string number_text(double value);
/// "NAME must be in [MIN, MAX] (UNIT), not VALUE" unless min <= value <= max. @throws InvalidArgument
void check_range(const Description& row, double value);
/// `name` with underscores as dashes (a Python keyword or batch column as the setting's name).
std::string canonical_name(std::string_view name);

/// The description of `row` with its default taken from `defaults`.
template <class T>
Description describe(const Setting<T>& row, const T& defaults = T{}) {
  Description d;
  d.name = row.name;
  d.unit = row.unit;
  d.help = row.help;
  d.type = row.type;
  d.commands = row.commands;
  d.min = row.min;
  d.max = row.max;
  d.exclusive_min = row.exclusive_min;
  d.length_power = row.length_power;
  if (row.choices) d.choices = row.choices();
  d.default_text = row.get(defaults);
  return d;
}

/// Every row of `rows` that belongs to `command` (all rows for command 0), described with `defaults`.
template <class T>
std::vector<Description> describe(std::span<const Setting<T>> rows, unsigned command = 0, const T& defaults = T{}) {
  std::vector<Description> out;
  for (const Setting<T>& row : rows)
    if (command == 0 || (row.commands & command) != 0) out.push_back(describe(row, defaults));
  return out;
}

/// Checks `text` against the row's type, range and choices, as every front end does.
/// @return the text to hand to the row's setter (a number scaled by `metres_per_unit` ^ length_power)
/// @throws InvalidArgument naming the setting
std::string checked_text(const Description& row, std::string_view text, double metres_per_unit = 1.0);

/// Sets the setting named `name` (dashes or underscores) of `target` from `text`.
/// @return false when no row has that name. @throws InvalidArgument for a malformed or out-of-range value
template <class T>
bool set(std::span<const Setting<T>> rows, T& target, std::string_view name, std::string_view text,
         double metres_per_unit = 1.0) {
  const std::string wanted = canonical_name(name);
  for (const Setting<T>& row : rows)
    if (row.name == wanted) {
      row.set(target, checked_text(describe(row, target), text, metres_per_unit));
      return true;
    }
  return false;
}

/// "unknown setting 'NAME' (known: a, b, ...)" for the rows of `command`. @throws InvalidArgument always
[[noreturn]] void throw_unknown(std::string_view name, const std::vector<Description>& known);

/// Sets every (name, text) pair of `given` on `target`, in order. @throws InvalidArgument for an unknown name (listing
/// the rows of `command`) or a bad value
template <class T>
void apply(std::span<const Setting<T>> rows, T& target, const std::vector<std::pair<std::string, std::string>>& given,
           unsigned command = 0, double metres_per_unit = 1.0) {
  for (const auto& [name, text] : given)
    if (!set(rows, target, name, text, metres_per_unit)) throw_unknown(name, describe(rows, command));
}

/// The rows of `inner` as rows of an outer struct that holds an Inner at `member(outer)`.
template <class Outer, class Inner, class Member>
std::vector<Setting<Outer>> lift(std::span<const Setting<Inner>> inner, Member member) {
  std::vector<Setting<Outer>> out;
  for (const Setting<Inner>& row : inner) {
    Setting<Outer> r;
    r.name = row.name;
    r.type = row.type;
    r.unit = row.unit;
    r.help = row.help;
    r.commands = row.commands;
    r.min = row.min;
    r.max = row.max;
    r.exclusive_min = row.exclusive_min;
    r.length_power = row.length_power;
    r.choices = row.choices;
    r.set = [set = row.set, member](Outer& o, std::string_view t) { set(member(o), t); };
    r.get = [get = row.get, member](const Outer& o) { return get(member(const_cast<Outer&>(o))); };
    out.push_back(std::move(r));
  }
  return out;
}

/// A row with its declaration filled in and no accessors yet (set `set`, `get` and, for a choice, `choices`).
template <class T>
Setting<T> row(std::string name, Type type, std::string unit, std::string help, unsigned commands,
               double min = -kUnbounded, double max = kUnbounded) {
  Setting<T> r;
  r.name = std::move(name);
  r.type = type;
  r.unit = std::move(unit);
  r.help = std::move(help);
  r.commands = commands;
  r.min = min;
  r.max = max;
  return r;
}

// Row builders: `field` is a function T& -> the field's reference.
template <class T, class Field>
Setting<T> number(std::string name, std::string unit, double min, double max, unsigned commands, std::string help,
                  Field field) {
  Setting<T> r = row<T>(std::move(name), Type::kNumber, std::move(unit), std::move(help), commands, min, max);
  r.set = [field](T& o, std::string_view t) { field(o) = parse_number("", t); };
  r.get = [field](const T& o) { return number_text(field(const_cast<T&>(o))); };
  return r;
}
template <class T, class Field>
Setting<T> integer(std::string name, int min, int max, unsigned commands, std::string help, Field field) {
  Setting<T> r = row<T>(std::move(name), Type::kInteger, "", std::move(help), commands, min, max);
  r.set = [field](T& o, std::string_view t) { field(o) = parse_integer("", t); };
  r.get = [field](const T& o) { return std::to_string(field(const_cast<T&>(o))); };
  return r;
}
template <class T, class Field>
Setting<T> flag(std::string name, unsigned commands, std::string help, Field field) {
  Setting<T> r = row<T>(std::move(name), Type::kFlag, "", std::move(help), commands);
  r.set = [field](T& o, std::string_view t) { field(o) = parse_flag("", t); };
  r.get = [field](const T& o) { return std::string(field(const_cast<T&>(o)) ? "on" : "off"); };
  return r;
}
/// A name from `choices`; `set` and `get` convert it to and from the field's enum.
template <class T>
Setting<T> choice(std::string name, unsigned commands, std::string help,
                  std::function<std::vector<std::string>()> choices, std::function<void(T&, std::string_view)> set,
                  std::function<std::string(const T&)> get) {
  Setting<T> r = row<T>(std::move(name), Type::kChoice, "", std::move(help), commands);
  r.choices = std::move(choices);
  r.set = std::move(set);
  r.get = std::move(get);
  return r;
}

}  // namespace hooke::settings
