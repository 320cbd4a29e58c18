// hooke batch STUDY.csv -o DIR [--scheduler ADDRESS|local] [--workers N] [--retry-failed] [--quiet]: a study table's
// jobs (calibrate and certify, or identify) as Dask tasks. Thin: the work is hooke.batch's (python/hooke/batch.py).
#include <memory>
#include <string>

#include "commands.hpp"
#include "python.hpp"

namespace hooke::cli {

Action add_batch_command(CLI::App& app) {
  struct Options {
    std::string study, out_dir, scheduler = "local";
    int workers = 0;
    bool retry_failed = false, quiet = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "batch", "Run a study table's jobs (calibrate + certify, or identify) on Dask distributed (docs/batch.md)");
  cmd->add_option("study", o->study, "Study table (CSV: name, mesh, young, poisson, method, density, strain, ...)")
      ->required();
  cmd->add_option("-o,--output", o->out_dir, "Study folder: results.csv and models/")->required();
  cmd->add_option("--scheduler", o->scheduler,
                  "A Dask scheduler's address (tcp://host:8786), or 'local': a local cluster of --workers processes")
      ->capture_default_str();
  cmd->add_option("--workers", o->workers, "Local cluster: worker processes (default: one per core)")
      ->check(CLI::Range(1, 4096));
  cmd->add_flag("--retry-failed", o->retry_failed, "Run again the jobs recorded as failed");
  cmd->add_flag("--quiet", o->quiet, "No progress bar");
  return [o] {
    std::vector<std::string> args{"-m", "hooke.batch", o->study, "-o", o->out_dir, "--scheduler", o->scheduler};
    if (o->workers > 0) args.insert(args.end(), {"--workers", std::to_string(o->workers)});
    if (o->retry_failed) args.emplace_back("--retry-failed");
    if (o->quiet) args.emplace_back("--quiet");
    return run_python(args);
  };
}

}  // namespace hooke::cli
