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
  return hooke::cli::parse_and_run(app, argc, argv, "hooke_viewer", view);
}
