#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <hooke/core/error.hpp>
#include <hooke/io/mesher.hpp>
#include <hooke/io/off.hpp>
#include <hooke/io/tetgen.hpp>
#include <string>
#include <utility>
#include <vector>

extern char** environ;

namespace hooke::io {
namespace {

namespace fs = std::filesystem;

std::string where(const mesh::Mesh& m) { return m.source.empty() ? std::string("the surface") : m.source; }

// A folder of its own under the system's temporary folder, removed with everything in it when this goes.
class TemporaryFolder {
 public:
  TemporaryFolder() {
    std::string pattern = (fs::temp_directory_path() / "hooke-tetgen-XXXXXX").string();
    if (!mkdtemp(pattern.data()))
      throw IoError("cannot make a temporary folder " + pattern + " for tetgen: " + std::strerror(errno));
    m_path = pattern;
  }
  ~TemporaryFolder() {
    std::error_code ignored;
    fs::remove_all(m_path, ignored);
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  const fs::path& path() const { return m_path; }

 private:
  fs::path m_path;
};

// The last `count` lines of a text file (TetGen's own account of a failure).
std::string tail(const fs::path& path, std::size_t count) {
  std::ifstream in(path);
  std::deque<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (line.empty()) continue;
    lines.push_back(line);
    if (lines.size() > count) lines.pop_front();
  }
  std::string out;
  for (const auto& l : lines) out += (out.empty() ? "" : " | ") + l;
  return out;
}

// Runs `args` (args[0] looked up on PATH), its output to `log`; returns the exit status.
int run_program(const std::vector<std::string>& args, const fs::path& log) {
  std::vector<char*> argv;
  std::vector<std::string> copy = args;
  for (auto& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned == ENOENT)
    throw InvalidArgument(
        "the tetgen mesher needs TetGen's program `tetgen`, which is not installed: "
        "scripts/setup.sh installs it (Debian package tetgen), or use --mesher netgen");
  if (spawned != 0) throw IoError("cannot start " + args[0] + ": " + std::strerror(spawned));
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw IoError("lost the child process " + args[0] + ": " + std::strerror(errno));
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 255;
}

std::string general(double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6g", v);
  return buffer;
}

// TetGen's switches for a piecewise linear complex kept as it is, with hooke's quality targets: "-pYq1.414/10".
std::string quality_switches() {
  return "-pYq" + general(mesh::kTetgenRadiusEdge) + "/" + general(mesh::kTetgenMinDihedralDegrees);
}

// TetGen on files: the surface as OFF, -p (a piecewise linear complex), -Y (its triangles kept: no Steiner point
// on the surface), -q (quality targets), -a (largest volume), -F (no .face/.edge files), -V (its statistics, for
// the log on failure).
mesh::Mesh tetgen_volume(const mesh::Mesh& surface, const mesh::TetrahedralizeOptions& o) {
  TemporaryFolder folder;
  const fs::path input = folder.path() / "surface.off";
  write_off(input, surface);
  const std::string switches = quality_switches() + "a" + general(mesh::regular_tet_volume(o.max_size)) + "FV";
  const fs::path log = folder.path() / "tetgen.log";
  const int status = run_program({"tetgen", switches, input.string()}, log);
  const fs::path ele = folder.path() / "surface.1.ele";
  if (status != 0 || !fs::exists(ele))
    throw InvalidMesh("tetgen " + switches + " could not mesh " + where(surface) + " (exit status " +
                      std::to_string(status) + "): " + tail(log, 4) + "; try --mesher netgen, or repair the surface");
  mesh::Mesh tets = read_tetgen(ele);
  tets.source = surface.source;
  // TetGen prints the input nodes back with fewer digits than they had: they are the input's (-Y), so the input's
  // own coordinates are put back where TetGen's agree with them to its printed precision.
  const int n = surface.node_count();
  if (tets.node_count() >= n) {
    const double tolerance = 1e-12 * (surface.nodes.cwiseAbs().maxCoeff() + 1e-300);
    if ((tets.nodes.topRows(n) - surface.nodes).cwiseAbs().maxCoeff() <= tolerance)
      tets.nodes.topRows(n) = surface.nodes;
  }
  return tets;
}

}  // namespace

mesh::VolumeMesher volume_mesher(mesh::Mesher mesher) {
  if (mesher == mesh::Mesher::kNetgen) return mesh::netgen_mesher();
  return {"tetgen 1.5 (program tetgen " + quality_switches() + ")", tetgen_volume};
}

mesh::Mesh tetrahedralize(mesh::Mesh surface, const mesh::TetrahedralizeOptions& options,
                          mesh::TetrahedralizeReport* report) {
  return mesh::tetrahedralize(std::move(surface), options, report, volume_mesher(options.mesher));
}

}  // namespace hooke::io
