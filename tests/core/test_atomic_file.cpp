#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <hooke/core/atomic_file.hpp>
#include <hooke/core/error.hpp>

namespace hooke {
namespace {

namespace fs = std::filesystem;

TEST(AtomicFile, FailedWriteLeavesTargetUntouchedAndNoTemporary) {
  const fs::path dir = fs::temp_directory_path() / "hooke_atomic_test";
  fs::create_directories(dir);
  const fs::path target = dir / "out.txt";
  write_file_atomically(target, [](std::ostream& o) { o << "first"; });
  EXPECT_THROW(write_file_atomically(target,
                                     [](std::ostream& o) {
                                       o << "half";
                                       throw InvalidArgument("boom");
                                     }),
               InvalidArgument);
  std::ifstream in(target);
  std::string content;
  in >> content;
  EXPECT_EQ(content, "first");
  int files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1);
  fs::remove_all(dir);
}

TEST(AtomicFile, MissingFolderIsAnIoError) {
  EXPECT_THROW(write_file_atomically("/nonexistent/dir/x.txt", [](std::ostream& o) { o << 1; }), IoError);
}

}  // namespace
}  // namespace hooke
