#pragma once
// Sub-commands of the hooke tool. Each registers its options on `app` and returns the action to run.
#include <CLI/CLI.hpp>
#include <functional>

namespace hooke::cli {

using Action = std::function<int()>;

/// `hooke fem`: linear or nonlinear FEM reference solve of a load case.
Action add_fem_command(CLI::App& app);
/// `hooke compare`: a calibrated spring model against the FEM reference.
Action add_compare_command(CLI::App& app);
/// `hooke reproduce lloyd2007`: the paper's Sec. 5 experiments and a report.
Action add_reproduce_command(CLI::App& app);
/// `hooke mesh info|convert`: inspect and convert meshes.
Action add_mesh_command(CLI::App& app);

}  // namespace hooke::cli
