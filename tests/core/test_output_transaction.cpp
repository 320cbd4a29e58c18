// OutputTransaction: nothing reaches the targets before commit(); an abandoned transaction leaves the previous files
// and no staging behind (and removes the folder it created); commit replaces files and swaps folders, the names
// given as `last` moved last; a file is not allowed to replace a folder, and then nothing moves.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <hooke/core/error.hpp>
#include <hooke/core/output_transaction.hpp>
#include <sstream>
#include <string>

namespace hooke {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path fresh(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "hooke_output_transaction" / name;
  fs::remove_all(dir);
  fs::create_directories(dir.parent_path());
  return dir;
}

TEST(OutputTransaction, AbandonedLeavesThePreviousFilesAndNoStaging) {
  const fs::path dir = fresh("abandon");
  fs::create_directories(dir);
  std::ofstream(dir / "a.txt") << "old";
  {
    OutputTransaction t;
    std::ofstream(t.stage_file(dir / "a.txt")) << "new";
    std::ofstream(t.stage_file(dir / "b.txt")) << "new";
  }
  EXPECT_EQ(slurp(dir / "a.txt"), "old");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  const fs::path created = fresh("created") / "deeper";
  {
    OutputTransaction t;
    std::ofstream(t.stage_folder(created) / "report.md") << "new";
  }
  EXPECT_FALSE(fs::exists(created));
  EXPECT_FALSE(fs::exists(created.parent_path()));
}

TEST(OutputTransaction, CommitReplacesFilesAndSwapsFolders) {
  const fs::path dir = fresh("commit");
  fs::create_directories(dir / "figures");
  std::ofstream(dir / "figures" / "old.png") << "old";
  std::ofstream(dir / "report.md") << "old";
  OutputTransaction t;
  const fs::path staging = t.stage_folder(dir);
  fs::create_directories(staging / "figures");
  std::ofstream(staging / "figures" / "new.png") << "new";
  std::ofstream(staging / "report.md") << "new";
  EXPECT_EQ(slurp(dir / "report.md"), "old");  // nothing moves before commit
  t.commit({"report.md"});
  EXPECT_EQ(slurp(dir / "report.md"), "new");
  EXPECT_TRUE(fs::exists(dir / "figures" / "new.png"));
  EXPECT_FALSE(fs::exists(dir / "figures" / "old.png"));
  EXPECT_FALSE(fs::exists(staging));
}

TEST(OutputTransaction, RefusesToReplaceAFolderByAFileBeforeMovingAnything) {
  const fs::path dir = fresh("refuse");
  fs::create_directories(dir / "b.txt");
  OutputTransaction t;
  std::ofstream(t.stage_file(dir / "a.txt")) << "new";
  std::ofstream(t.stage_file(dir / "b.txt")) << "new";
  EXPECT_THROW(t.commit(), IoError);
  EXPECT_FALSE(fs::exists(dir / "a.txt"));
}

TEST(OutputTransaction, AFileIsNotAFolder) {
  const fs::path dir = fresh("file");
  fs::create_directories(dir);
  std::ofstream(dir / "plain") << "x";
  OutputTransaction t;
  EXPECT_THROW(t.stage_folder(dir / "plain"), IoError);
  EXPECT_THROW(t.stage_file(dir / "plain" / "a.vtu"), IoError);
}

}  // namespace
}  // namespace hooke
