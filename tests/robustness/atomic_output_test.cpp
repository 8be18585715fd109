// The preparer's output appears whole or not at all, also when it fails half way through putting
// the files in place: the directory then holds exactly what it held before.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "codegen/model_writer.h"
#include "codegen/prepare_error.h"

namespace octopoint::prepare {
namespace {

namespace fs = std::filesystem;

class AtomicOutputTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("octopoint_atomic_output_" + std::string(info->name()) + "_" +
                                        std::to_string(::getpid()));
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static std::string contentsOf(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  static void put(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }
  // Every entry of the directory, hidden ones (a staging directory left behind) included.
  std::set<std::string> entries() const {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_)) names.insert(entry.path().filename().string());
    return names;
  }

  fs::path dir_;
};

TEST_F(AtomicOutputTest, WritesEveryFileAndLeavesNothingElse) {
  writeFilesAtomically(dir_, {{"a.txt", "alpha"}, {"b.txt", "beta"}});
  EXPECT_EQ(entries(), (std::set<std::string>{"a.txt", "b.txt"}));
  EXPECT_EQ(contentsOf(dir_ / "a.txt"), "alpha");
  EXPECT_EQ(contentsOf(dir_ / "b.txt"), "beta");
}

TEST_F(AtomicOutputTest, ReplacesTheFilesOfAnEarlierRun) {
  writeFilesAtomically(dir_, {{"a.txt", "old a"}, {"b.txt", "old b"}});
  writeFilesAtomically(dir_, {{"a.txt", "new a"}, {"b.txt", "new b"}});
  EXPECT_EQ(entries(), (std::set<std::string>{"a.txt", "b.txt"}));
  EXPECT_EQ(contentsOf(dir_ / "a.txt"), "new a");
  EXPECT_EQ(contentsOf(dir_ / "b.txt"), "new b");
}

// The second of three renames fails (its name is taken by a directory, which is never replaced):
// the first file, already in place, must be taken out again and the earlier run's one restored.
TEST_F(AtomicOutputTest, AFailedRenameHalfWayRestoresTheEarlierFiles) {
  fs::create_directories(dir_ / "b.txt");
  put(dir_ / "b.txt" / "keep", "x");
  put(dir_ / "a.txt", "old a");
  try {
    writeFilesAtomically(dir_, {{"a.txt", "new a"}, {"b.txt", "new b"}, {"c.txt", "new c"}});
    FAIL() << "no error although b.txt cannot be replaced";
  } catch (const PrepareError& error) {
    EXPECT_NE(std::string(error.what()).find("b.txt: cannot rename into place"), std::string::npos)
        << error.what();
  }
  EXPECT_EQ(entries(), (std::set<std::string>{"a.txt", "b.txt"}));
  EXPECT_EQ(contentsOf(dir_ / "a.txt"), "old a");
  EXPECT_TRUE(fs::is_directory(dir_ / "b.txt"));
}

TEST_F(AtomicOutputTest, AFailedWriteRemovesTheDirectoryItMade) {
  // A name with a missing subdirectory cannot be written: the failure comes after the first file.
  EXPECT_THROW(writeFilesAtomically(dir_, {{"a.txt", "alpha"}, {"missing/b.txt", "beta"}}), PrepareError);
  EXPECT_FALSE(fs::exists(dir_));
}

TEST_F(AtomicOutputTest, AFailedWriteLeavesAnExistingDirectoryAsItWas) {
  fs::create_directories(dir_);
  put(dir_ / "a.txt", "old a");
  EXPECT_THROW(writeFilesAtomically(dir_, {{"a.txt", "new a"}, {"missing/b.txt", "beta"}}), PrepareError);
  EXPECT_EQ(entries(), (std::set<std::string>{"a.txt"}));
  EXPECT_EQ(contentsOf(dir_ / "a.txt"), "old a");
}

}  // namespace
}  // namespace octopoint::prepare
