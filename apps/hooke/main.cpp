// hooke: command-line front end. Thin: every computation is a library call.
#include <cstdio>
#include <hooke/core/error.hpp>
#include <hooke/core/version.hpp>
#include <string>

#include "commands.hpp"
#ifdef HOOKE_HAVE_VIEWER
#include "view_command.hpp"
#endif

int main(int argc, char** argv) {
  CLI::App app{"hooke: mass-spring models calibrated from E and nu, validated against FEM"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "hooke " + std::string(hooke::kVersion));
  const hooke::cli::Action fem = hooke::cli::add_fem_command(app);
  const hooke::cli::Action mesh = hooke::cli::add_mesh_command(app);
  const hooke::cli::Action compare = hooke::cli::add_compare_command(app);
  const hooke::cli::Action reproduce = hooke::cli::add_reproduce_command(app);
  const hooke::cli::Action simulate = hooke::cli::add_simulate_command(app);
  const hooke::cli::Action bench = hooke::cli::add_bench_command(app);
  const hooke::cli::Action calibrate = hooke::cli::add_calibrate_command(app);
  const hooke::cli::Action identify = hooke::cli::add_identify_command(app);
  const hooke::cli::Action batch = hooke::cli::add_batch_command(app);
  CLI::App* view_cmd =
      app.add_subcommand("view", "Interactive viewer: grab the model with the mouse, change E and nu live");
#ifdef HOOKE_HAVE_VIEWER
  const hooke::cli::Action view = hooke::viewer::add_view_options(view_cmd);
#else
  view_cmd->allow_extras();
  const hooke::cli::Action view = []() -> int {
    throw hooke::InvalidArgument(
        "this hooke was built without the viewer: install GLFW, OpenGL and Dear ImGui (scripts/setup.sh) and rebuild");
  };
#endif
  return hooke::cli::parse_and_run(app, argc, argv, "hooke", [&]() -> int {
    if (app.got_subcommand("fem")) return fem();
    if (app.got_subcommand("mesh")) return mesh();
    if (app.got_subcommand("compare")) return compare();
    if (app.got_subcommand("reproduce")) return reproduce();
    if (app.got_subcommand("simulate")) return simulate();
    if (app.got_subcommand("bench")) return bench();
    if (app.got_subcommand("calibrate")) return calibrate();
    if (app.got_subcommand("identify")) return identify();
    if (app.got_subcommand("batch")) return batch();
    if (app.got_subcommand("view")) return view();
    return 2;
  });
}
