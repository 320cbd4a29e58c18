#pragma once
// hooke.Model's certificate cases as Python dicts, shared by the Model class and hooke.certify.
#include <pybind11/pybind11.h>
#include <hooke/calibrate/calibrated_model.hpp>

namespace hooke::python {

/// One certificate case as {"load", "strain", "max_error", "mean_error", "relative_l2"}.
pybind11::dict certificate_case(const calibrate::CertificateCase& c);

}  // namespace hooke::python
