#include "python.hpp"

#include <spawn.h>
#include <sys/wait.h>

#include <cstdlib>
#include <hooke/core/error.hpp>
#include <string>
#include <system_error>

#ifndef HOOKE_SCRIPT_DIR
#define HOOKE_SCRIPT_DIR "scripts"
#endif

extern char** environ;

namespace hooke::cli {
namespace {

// The build tree's Python package when this executable lies in the build tree that made it.
void use_build_tree_package() {
#if defined(HOOKE_BUILD_DIR) && defined(HOOKE_BUILD_PYTHON_DIR)
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::string build = HOOKE_BUILD_DIR;
  if (ec || self.string().rfind(build + "/", 0) != 0) return;
  const char* old = std::getenv("PYTHONPATH");
  std::string path = HOOKE_BUILD_PYTHON_DIR;
  if (old && *old) path.append(":").append(old);
  setenv("PYTHONPATH", path.c_str(), 1);
#endif
}

}  // namespace

int run_python(const std::vector<std::string>& args) {
  const char* python = std::getenv("HOOKE_PYTHON");
  std::vector<std::string> all{python ? python : "/usr/bin/python3"};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  setenv("MPLBACKEND", "Agg", 1);
  static const bool path_set = (use_build_tree_package(), true);  // once: a command may start Python twice
  (void)path_set;
  pid_t pid = 0;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0)
    throw IoError("cannot start " + all[0] + " (scripts/setup.sh installs Debian's python3)");
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) throw IoError("lost the child " + all[0]);
  if (WIFSIGNALED(status)) {
    std::string message = all[0];
    for (const auto& a : args) message.append(" ").append(a);
    message.append(" ended on signal ").append(std::to_string(WTERMSIG(status)));
    throw IoError(message);
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 4;
}

void plot_figures(const std::vector<std::filesystem::path>& specs) {
  if (specs.empty()) return;
  const char* script = std::getenv("HOOKE_PLOT_SCRIPT");
  std::vector<std::string> args{script ? script : HOOKE_SCRIPT_DIR "/plot_figures.py"};
  for (const auto& s : specs) args.push_back(s.string());
  if (run_python(args) != 0) throw IoError("drawing the figures with " + args[0] + " failed (see its message above)");
}

}  // namespace hooke::cli
