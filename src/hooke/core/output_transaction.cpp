#include <fcntl.h>
#include <stdio.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <hooke/core/atomic_file.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/output_transaction.hpp>
#include <random>

namespace hooke {
namespace fs = std::filesystem;

namespace {

// Moves `from` onto `to`. An existing folder at `to` is exchanged with `from` atomically and the old one (now at
// `from`) removed, so `to` never disappears; a file is replaced by rename(2), which is atomic.
void move_into_place(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  if (fs::is_directory(to, ec) && fs::is_directory(from, ec)) {
#ifdef SYS_renameat2
    if (syscall(SYS_renameat2, AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), 2 /* RENAME_EXCHANGE */) == 0) {
      fs::remove_all(from, ec);
      return;
    }
#endif
    fs::remove_all(to, ec);  // no exchange on this file system: a short window without the folder
  }
  fs::rename(from, to, ec);
  if (ec) throw IoError("cannot move '" + from.string() + "' to '" + to.string() + "': " + ec.message());
}

}  // namespace

OutputTransaction::OutputTransaction() {
  std::random_device entropy;
  char id[16];
  std::snprintf(id, sizeof id, "%08x", static_cast<unsigned>(entropy()));
  m_id = id;
}

OutputTransaction::~OutputTransaction() {
  if (m_committed) return;
  std::error_code ec;
  for (const auto& [staging, target] : m_files) fs::remove(staging, ec);
  for (const fs::path& f : m_folders) fs::remove_all(f, ec);
  for (auto it = m_created.rbegin(); it != m_created.rend(); ++it) fs::remove(*it, ec);  // only when empty
}

void OutputTransaction::make_folder(const fs::path& dir) {
  std::vector<fs::path> missing;
  std::error_code ec;
  for (fs::path p = dir; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    missing.push_back(p);
    if (p == p.parent_path()) break;
  }
  create_output_folder(dir);
  m_created.insert(m_created.end(), missing.rbegin(), missing.rend());
}

fs::path OutputTransaction::stage_file(const fs::path& target) {
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  make_folder(dir);
  const fs::path staging = dir / (target.stem().string() + ".staging-" + m_id + target.extension().string());
  m_files.emplace_back(staging, target);
  return staging;
}

fs::path OutputTransaction::stage_folder(const fs::path& dir) {
  make_folder(dir);
  const fs::path staging = dir / (".staging-" + m_id);
  std::error_code ec;
  fs::create_directories(staging, ec);
  if (ec) throw IoError("cannot create '" + staging.string() + "': " + ec.message());
  m_folders.push_back(staging);
  return staging;
}

void OutputTransaction::commit(const std::vector<std::string>& last) {
  std::error_code ec;
  // What a rename would refuse is refused before anything moves: a file cannot replace a folder, nor the reverse.
  for (const auto& [staging, target] : m_files)
    if (fs::exists(staging, ec) && fs::exists(target, ec) &&
        fs::is_directory(staging, ec) != fs::is_directory(target, ec))
      throw IoError("cannot replace '" + target.string() + "' (" +
                    (fs::is_directory(target, ec) ? "a folder" : "a file") +
                    ") by the new output; nothing was written");
  for (const auto& [staging, target] : m_files)
    if (fs::exists(staging, ec)) move_into_place(staging, target);
  for (const fs::path& folder : m_folders) {
    std::vector<fs::path> entries;
    for (const auto& e : fs::directory_iterator(folder, ec)) entries.push_back(e.path());
    auto rank = [&](const fs::path& p) {
      const auto it = std::find(last.begin(), last.end(), p.filename().string());
      return it == last.end() ? -1 : static_cast<int>(it - last.begin());
    };
    std::stable_sort(entries.begin(), entries.end(), [&](const fs::path& a, const fs::path& b) {
      return rank(a) != rank(b) ? rank(a) < rank(b) : a.filename() < b.filename();
    });
    for (const fs::path& e : entries) move_into_place(e, folder.parent_path() / e.filename());
    fs::remove_all(folder, ec);
  }
  m_committed = true;
}

}  // namespace hooke
