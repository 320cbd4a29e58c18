#pragma once
/// The certificate a calibrated model is shipped with: its node error against the linear FEM of its own mesh and
/// material on the papers' load cases (Lloyd et al. 2007, Sec. 5), written into the model file.
#include <hooke/calibrate/calibrated_model.hpp>
#include <hooke/material/material.hpp>
#include <hooke/model/load_case.hpp>
#include <vector>

namespace hooke::experiments {

/// The certificate a model is shipped with (`hooke calibrate --certify`): stretch, compress and shear (or the cases
/// `loads` names, in its order) at mean linear-FEM strain `strain` against the linear FEM, each case's max / mean
/// node error (m) and relative L2.
/// @throws SolverFailure when a solve does not converge; InvalidArgument for strain <= 0 or no load
std::vector<calibrate::CertificateCase> certify(const calibrate::CalibratedModel& model, double strain = 0.01,
                                                int layers = 4,
                                                const std::vector<model::LoadKind>& loads = {model::LoadKind::kStretch,
                                                                                             model::LoadKind::kCompress,
                                                                                             model::LoadKind::kShear});

/// The certificate of a model made for a law up to a strain (`hooke calibrate --law L --strain-range S --certify`):
/// stretch, compress and shear (or `loads`) under displacement control at 1 % and at `strain_range` against the FEM
/// of `law` (the model's material with that law), each case's node errors, relative L2 and force error.
/// @throws SolverFailure when a solve does not converge; InvalidArgument for strain_range <= 0 or no load
std::vector<calibrate::CertificateCase> certify_range(const calibrate::CalibratedModel& model, material::Law law,
                                                      double strain_range, int layers = 4,
                                                      const std::vector<model::LoadKind>& loads = {
                                                          model::LoadKind::kStretch, model::LoadKind::kCompress,
                                                          model::LoadKind::kShear});

}  // namespace hooke::experiments
