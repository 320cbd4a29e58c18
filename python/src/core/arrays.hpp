#pragma once
// numpy views of hooke's Eigen storage (no copies) and checked conversions of numpy inputs: a wrong shape, dtype
// or a NaN raises ValueError naming the argument.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <hooke/core/types.hpp>
#include <string>

namespace hooke::python {

namespace py = pybind11;

// A rows x cols C-contiguous view of `data`, kept alive by `owner`; read-only unless `writable`.
template <typename T>
py::array_t<T> view(T* data, Eigen::Index rows, Eigen::Index cols, py::handle owner, bool writable) {
  py::array_t<T> a({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(cols)},
                   {static_cast<py::ssize_t>(cols * sizeof(T)), static_cast<py::ssize_t>(sizeof(T))}, data, owner);
  if (!writable) py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

// A flat view of `data` (size n), kept alive by `owner`.
template <typename T>
py::array_t<T> flat_view(T* data, Eigen::Index n, py::handle owner, bool writable) {
  py::array_t<T> a({static_cast<py::ssize_t>(n)}, {static_cast<py::ssize_t>(sizeof(T))}, data, owner);
  if (!writable) py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

// A property getter: a flat view of the VecX that `field` picks from the bound object, kept alive by it.
template <typename Class, typename Field>
auto flat_property(Field field, bool writable) {
  return [field, writable](py::object self) {
    auto& v = field(self.cast<Class&>());
    return flat_view(const_cast<double*>(v.data()), v.size(), self, writable);
  };
}

// A property getter: the flat VecX that `field` picks, viewed as (size / dim) x dim rows (read-only).
template <typename Class, typename Field, typename Dim>
auto rows_property(Field field, Dim dim) {
  return [field, dim](py::object self) {
    auto& object = self.cast<Class&>();
    auto& v = field(object);
    const int d = dim(object);
    return view(const_cast<double*>(v.data()), v.size() / d, d, self, false);
  };
}

// `value` as rows x cols doubles (cols = -1: any); ValueError naming `name` on a wrong shape or a non-finite
// entry. rows = -1: any.
RowMatX matrix_argument(const py::handle& value, const char* name, Eigen::Index rows, Eigen::Index cols);
// `value` as a vector of doubles of size n (-1: any), finite.
VecX vector_argument(const py::handle& value, const char* name, Eigen::Index n);
// `value` as rows x cols integers.
RowMatXi index_argument(const py::handle& value, const char* name, Eigen::Index cols);

}  // namespace hooke::python
