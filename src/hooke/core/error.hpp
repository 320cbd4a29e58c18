#pragma once
/// Typed errors for bad user input and failed numerics. Messages speak the user's terms
/// ("tet 412 of cylinder.msh is inverted"), never source locations.
#include <cstdint>
#include <stdexcept>
#include <string>

namespace hooke {

/// Base of every error hooke throws on purpose.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

/// A file could not be read or parsed. `line` is 1-based for text formats; for binary formats
/// `byte_offset` is set instead (and `line` is 0).
class ParseError : public Error {
 public:
  ParseError(std::string file, std::int64_t line, const std::string& what_failed);
  /// Binary-format variant: names a byte offset instead of a line.
  static ParseError at_byte(std::string file, std::int64_t byte_offset, const std::string& what_failed);
  /// Structured-format variant (JSON model files): names an entry ("springs[12]") instead of a line.
  static ParseError at_entry(std::string file, const std::string& entry, const std::string& what_failed);
  const std::string& file() const { return m_file; }
  std::int64_t line() const { return m_line; }
  std::int64_t byte_offset() const { return m_byte_offset; }

 private:
  ParseError(std::string file, std::int64_t line, std::int64_t byte_offset, const std::string& message);
  std::string m_file;
  std::int64_t m_line = 0;
  std::int64_t m_byte_offset = -1;
};

/// A file could not be opened, written or renamed.
class IoError : public Error {
 public:
  using Error::Error;
};

/// A mesh violates a precondition: index out of range, degenerate or inverted element, ...
/// `element` is the 0-based element index in file order, or -1 when the problem is not one element.
class InvalidMesh : public Error {
 public:
  InvalidMesh(const std::string& message, std::int64_t element = -1) : Error(message), m_element(element) {}
  std::int64_t element() const { return m_element; }

 private:
  std::int64_t m_element;
};

/// Material parameters out of their physical range (E <= 0, nu outside (-1, 0.5), t <= 0).
class InvalidMaterial : public Error {
 public:
  using Error::Error;
};

/// An argument outside its documented range (a negative strain, an unknown method name, ...).
class InvalidArgument : public Error {
 public:
  using Error::Error;
};

/// A solver did not converge, or converged to an unstable equilibrium.
class SolverFailure : public Error {
 public:
  using Error::Error;
};

/// A result overflowed (an infinite or NaN value about to be written): nothing is written. A SolverFailure, so
/// front ends report it like one (exit 3).
class NonFiniteResult : public SolverFailure {
 public:
  using SolverFailure::SolverFailure;
};

}  // namespace hooke
