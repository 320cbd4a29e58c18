#include <cmath>
#include <core/arrays.hpp>

namespace hooke::python {
namespace {

[[noreturn]] void bad(const char* name, const std::string& what) {
  throw py::value_error(std::string(name) + ": " + what);
}

py::array_t<double, py::array::c_style | py::array::forcecast> as_doubles(const py::handle& value, const char* name) {
  py::array a = py::array::ensure(value);
  if (!a) bad(name, "expected a numpy array or a sequence of numbers");
  if (a.dtype().kind() != 'f' && a.dtype().kind() != 'i' && a.dtype().kind() != 'u')
    bad(name, "expected numbers, got dtype " + std::string(py::str(a.dtype())));
  return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
}

}  // namespace

RowMatX matrix_argument(const py::handle& value, const char* name, Eigen::Index rows, Eigen::Index cols) {
  const auto a = as_doubles(value, name);
  if (a.ndim() != 2) bad(name, "expected a 2-D array, got " + std::to_string(a.ndim()) + " dimensions");
  if ((rows >= 0 && a.shape(0) != rows) || (cols >= 0 && a.shape(1) != cols))
    bad(name, "expected shape (" + (rows >= 0 ? std::to_string(rows) : std::string("N")) + ", " +
                  (cols >= 0 ? std::to_string(cols) : std::string("M")) + "), got (" + std::to_string(a.shape(0)) +
                  ", " + std::to_string(a.shape(1)) + ")");
  RowMatX m = Eigen::Map<const RowMatX>(a.data(), a.shape(0), a.shape(1));
  if (!m.allFinite()) bad(name, "contains NaN or infinity");
  return m;
}

VecX vector_argument(const py::handle& value, const char* name, Eigen::Index n) {
  const auto a = as_doubles(value, name);
  if (a.ndim() != 1) bad(name, "expected a 1-D array, got " + std::to_string(a.ndim()) + " dimensions");
  if (n >= 0 && a.shape(0) != n)
    bad(name, "expected " + std::to_string(n) + " entries, got " + std::to_string(a.shape(0)));
  VecX v = Eigen::Map<const VecX>(a.data(), a.shape(0));
  if (!v.allFinite()) bad(name, "contains NaN or infinity");
  return v;
}

RowMatXi index_argument(const py::handle& value, const char* name, Eigen::Index cols) {
  py::array a = py::array::ensure(value);
  if (!a || (a.dtype().kind() != 'i' && a.dtype().kind() != 'u')) bad(name, "expected an integer array");
  const auto i = py::array_t<int, py::array::c_style | py::array::forcecast>::ensure(a);
  if (i.ndim() != 2 || (cols >= 0 && i.shape(1) != cols)) bad(name, "expected shape (N, " + std::to_string(cols) + ")");
  return Eigen::Map<const RowMatXi>(i.data(), i.shape(0), i.shape(1));
}

}  // namespace hooke::python
