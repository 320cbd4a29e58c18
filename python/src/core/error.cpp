// hooke's error types as Python exceptions carrying the same facts (file, line, element), never a bare
// RuntimeError: Error is the base; ParseError (.file, .line, .byte_offset), IoError, InvalidMesh (.element),
// InvalidMaterial, InvalidArgument (also a ValueError), SolverFailure.
#include <bindings.hpp>
#include <hooke/core/error.hpp>

namespace py = pybind11;

namespace hooke::python {
namespace {

// Raises `type(message)` with the given attributes set on the instance.
void raise(const py::object& type, const char* message, const py::dict& attributes = py::dict()) {
  py::object instance = type(message);
  for (auto item : attributes) py::setattr(instance, item.first, item.second);
  PyErr_SetObject(type.ptr(), instance.ptr());
}

}  // namespace

void define_error(py::module_& m) {
  static py::exception<Error> error(m, "Error", PyExc_RuntimeError);
  static py::exception<ParseError> parse_error(m, "ParseError", error.ptr());
  static py::exception<IoError> io_error(m, "IoError", error.ptr());
  static py::exception<InvalidMesh> invalid_mesh(m, "InvalidMesh", error.ptr());
  static py::exception<InvalidMaterial> invalid_material(m, "InvalidMaterial", error.ptr());
  py::object bases = py::make_tuple(error, py::handle(PyExc_ValueError));
  static py::object invalid_argument =
      py::reinterpret_steal<py::object>(PyErr_NewException("_hooke.InvalidArgument", bases.ptr(), nullptr));
  m.attr("InvalidArgument") = invalid_argument;
  static py::exception<SolverFailure> solver_failure(m, "SolverFailure", error.ptr());
  error.doc() = "Base of every error hooke raises on purpose.";
  parse_error.doc() = "A file could not be parsed: .file, .line (1-based; 0 for binary formats), .byte_offset.";
  invalid_mesh.doc() = "A mesh violates a precondition: .element is the 0-based element index or -1.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const ParseError& e) {
      py::dict a;
      a["file"] = e.file();
      a["line"] = e.line();
      a["byte_offset"] = e.byte_offset();
      raise(parse_error, e.what(), a);
    } catch (const IoError& e) {
      raise(io_error, e.what());
    } catch (const InvalidMesh& e) {
      py::dict a;
      a["element"] = e.element();
      raise(invalid_mesh, e.what(), a);
    } catch (const InvalidMaterial& e) {
      raise(invalid_material, e.what());
    } catch (const InvalidArgument& e) {
      raise(invalid_argument, e.what());
    } catch (const SolverFailure& e) {
      raise(solver_failure, e.what());
    } catch (const Error& e) {
      raise(error, e.what());
    }
  });
}

}  // namespace hooke::python
