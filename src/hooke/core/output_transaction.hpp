#pragma once
/// A command's outputs written as one transaction: everything goes to staging names first and is moved
/// into place by commit(), the index file (a report, a .pvd) last. A command that fails before commit() leaves the
/// previous outputs untouched and no staging files behind (the destructor removes them, and the output folder when
/// this transaction created it and it is still empty).
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace hooke {

class OutputTransaction {
 public:
  OutputTransaction();
  ~OutputTransaction();
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;

  /// Where to write the file `target` now: "<stem>.staging-ID<ext>" beside it (the extension kept, for writers
  /// that choose the format by it, and for TetGen's sibling files, which share the staged stem). Creates the folder.
  /// @throws IoError when the folder is a file or cannot be created or written
  std::filesystem::path stage_file(const std::filesystem::path& target);
  /// A folder to write outputs into under their final names, each to be moved into `dir` at commit():
  /// "<dir>/.staging-ID/". Creates both.
  /// @throws IoError as stage_file
  std::filesystem::path stage_folder(const std::filesystem::path& dir);
  /// Moves everything staged into place: the staged files in the order staged (those never written are skipped),
  /// then the entries of each staged folder, the names in `last` after the others and in that order. A folder entry
  /// replacing an existing folder is swapped with it atomically (renameat2 RENAME_EXCHANGE), so no name is ever
  /// missing; the old contents are then removed.
  /// @throws IoError when a rename fails
  void commit(const std::vector<std::string>& last = {});

 private:
  std::string m_id;
  std::vector<std::pair<std::filesystem::path, std::filesystem::path>> m_files;  // staging, target
  std::vector<std::filesystem::path> m_folders;                                  // staging folders
  std::vector<std::filesystem::path> m_created;                                  // output folders made here
  bool m_committed = false;

  void make_folder(const std::filesystem::path& dir);
};

}  // namespace hooke
