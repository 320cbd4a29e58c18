#pragma once
/// Model files: a calibrated model written for other engines and read back (schema in docs/model_format.md).
#include <filesystem>
#include <hooke/calibrate/calibrated_model.hpp>
#include <string>

namespace hooke::calibrate {

/// Version of the JSON schema this build writes and reads.
inline constexpr int kModelSchemaVersion = 1;

/// Writes `model` in the format named by the extension, atomically:
/// - .json: the whole model (nodes, elements, springs, volume and surface terms, masses, material, method and
///   equation, hooke's version, warnings, certificate), readable by read_model;
/// - .vtu: the springs as line cells with cell data "stiffness" (N/m) and "rest_length" (m) and point data
///   "mass" (kg), plus the elements in `<stem>_elements.vtu` beside it (both appear together or neither);
/// - .csv: one spring a line, "i,j,stiffness_n_per_m,rest_length_m" (0-based node indices).
/// @throws InvalidArgument for another extension or a model validate_model rejects; IoError
void write_model(const std::filesystem::path& path, const CalibratedModel& model);

/// The JSON text write_model writes for .json (one spring, node or element a line).
std::string model_json(const CalibratedModel& model);

/// Reads a .json model file and validates it (validate_model).
/// @throws IoError when it cannot be read; ParseError naming the file and the line (JSON syntax) or the entry
///   ("springs[12]: node index 900 is out of range") for a wrong schema version, a missing or unknown key, a
///   value of the wrong type, an index out of range, k < 0, l0 <= 0, a non-finite number
CalibratedModel read_model(const std::filesystem::path& path);

/// Parses model JSON text; `source` names it in messages. Same checks as read_model.
CalibratedModel parse_model(const std::string& text, const std::string& source);

}  // namespace hooke::calibrate
