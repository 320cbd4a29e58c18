#pragma once
/// The model factory's settings by name (ModelOptions; docs/architecture.md, "Settings"): the method, the density,
/// the term law, the surface model's options and how a closed surface is made into tets. Every command that makes a
/// model takes them (hooke calibrate, compare, simulate, view; Python's hooke.calibrate; the batch table); the tet
/// options also `hooke mesh tetrahedralize` and hooke.tetrahedralize, the term law also `hooke bench`; the rows marked
/// settings::kView are the viewer's live settings (its panel and its scripts' `set`, which recalibrate).
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/core/settings.hpp>
#include <span>

namespace hooke::calibrate {

/// Every user-settable field of ModelOptions, in the order --help lists them.
std::span<const settings::Setting<ModelOptions>> model_settings();

}  // namespace hooke::calibrate
