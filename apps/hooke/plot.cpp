#include "plot.hpp"

#include <spawn.h>
#include <sys/wait.h>

#include <cstdlib>
#include <hooke/core/error.hpp>
#include <string>

#ifndef HOOKE_SCRIPT_DIR
#define HOOKE_SCRIPT_DIR "scripts"
#endif

extern char** environ;

namespace hooke::cli {

void plot_figures(const std::vector<std::filesystem::path>& specs) {
  if (specs.empty()) return;
  const char* python = std::getenv("HOOKE_PYTHON");
  const char* script = std::getenv("HOOKE_PLOT_SCRIPT");
  std::vector<std::string> args{python ? python : "/usr/bin/python3",
                                script ? script : HOOKE_SCRIPT_DIR "/plot_figures.py"};
  for (const auto& s : specs) args.push_back(s.string());
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  setenv("MPLBACKEND", "Agg", 1);
  pid_t pid = 0;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0)
    throw IoError("cannot start " + args[0] + " to draw the figures (install python3-matplotlib)");
  int status = 0;
  if (waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw IoError("drawing the figures with " + args[1] + " failed (see its message above)");
}

}  // namespace hooke::cli
