#pragma once
// `hooke view` and `hooke_viewer`: the same options and the same run, registered on a subcommand or on a program.
#include <CLI/CLI.hpp>
#include <functional>

namespace hooke::viewer {

/// Registers the viewer's options on `cmd` (MESH or --model, E, nu, method, integrator, dt, script, screenshot, ...)
/// and returns the action that runs the viewer with them (exit code: 0, 2 for bad input or no display, 3 for a
/// solver failure).
std::function<int()> add_view_options(CLI::App* cmd);

}  // namespace hooke::viewer
