// hooke reproduce lloyd2007 [-o DIR]: the experiments of Lloyd et al. 2007, Sec. 5, with a report.
#include <cstdio>
#include <hooke/core/error.hpp>
#include <hooke/experiments/reproduce_lloyd2007.hpp>
#include <memory>
#include <string>

#include "commands.hpp"

#ifndef HOOKE_MESH_DIR
#define HOOKE_MESH_DIR "data/meshes"
#endif

namespace hooke::cli {

Action add_reproduce_command(CLI::App& app) {
  struct Options {
    std::string paper, out_dir = "out/lloyd2007", mesh_dir = HOOKE_MESH_DIR;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("reproduce", "Reproduce a paper's experiments and write a report");
  cmd->add_option("paper", o->paper, "lloyd2007")->required();
  cmd->add_option("-o,--output", o->out_dir, "Report folder")->capture_default_str();
  cmd->add_option("--meshes", o->mesh_dir, "Folder of the committed meshes")->capture_default_str();
  return [o] {
    if (o->paper != "lloyd2007") throw InvalidArgument("unknown paper '" + o->paper + "' (available: lloyd2007)");
    const auto cases = experiments::reproduce_lloyd2007(o->mesh_dir);
    experiments::write_lloyd2007_report(o->out_dir, cases);
    for (const auto& c : cases)
      std::printf("%-34s %-18s ours %7.3f / %6.3f cm   paper %6.3f / %6.3f cm   fit %6.3f / %6.3f cm   %s\n",
                  c.id.c_str(), c.method.c_str(), c.max_error_cm, c.mean_error_cm, c.paper_max_cm, c.paper_mean_cm,
                  c.fit_max_error_cm, c.fit_mean_error_cm, c.status.c_str());
    std::printf("wrote %s/lloyd2007.md and lloyd2007.json\n", o->out_dir.c_str());
    return 0;
  };
}

}  // namespace hooke::cli
