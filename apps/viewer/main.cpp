// hooke_viewer: the interactive viewer as its own program (the same as `hooke view`).
#include <cstdio>
#include <hooke/core/error.hpp>
#include <hooke/core/version.hpp>
#include <string>

#include <commands.hpp>
#include "view_command.hpp"

int main(int argc, char** argv) {
  CLI::App app{"hooke_viewer: grab a calibrated model with the mouse, change E and nu live, see its error against FEM"};
  app.set_version_flag("--version", "hooke_viewer " + std::string(hooke::kVersion));
  const auto view = hooke::viewer::add_view_options(&app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    hooke::cli::require_finite_numbers(app);
    return view();
  } catch (const hooke::SolverFailure& e) {
    std::fprintf(stderr, "hooke_viewer: solver failure: %s\n", e.what());
    return 3;
  } catch (const hooke::Error& e) {
    std::fprintf(stderr, "hooke_viewer: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hooke_viewer: internal error: %s\n", e.what());
    return 4;
  }
}
