// The output-file rule (cli/output_file.h): outputs that exist must be regular files, and what a
// tool writes appears whole or not at all, also when a signal comes while it is written.
#include "cli/output_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli/error.h"
#include "cli/signals.h"

namespace octopoint::cli {
namespace {

namespace fs = std::filesystem;

class OutputFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("octopoint_output_file_" + std::string(info->name()) + "_" +
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
  // Every entry of the directory, hidden ones (a staging folder or temporary left behind) included.
  std::set<std::string> entries() const {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_))
      names.insert(entry.path().filename().string());
    return names;
  }
  static std::string messageOf(const std::function<void()>& action) {
    try {
      action();
    } catch (const Error& error) {
      return error.what();
    }
    return "no error";
  }

  fs::path dir_;
};

TEST_F(OutputFileTest, WritesEveryFileAndLeavesNothingElse) {
  writeFilesAtomically(dir_, {{"a.txt", "alpha"}, {"b.txt", "beta"}});
  EXPECT_EQ(entries(), (std::set<std::string>{"a.txt", "b.txt"}));
  EXPECT_EQ(contentsOf(dir_ / "a.txt"), "alpha");
  EXPECT_EQ(contentsOf(dir_ / "b.txt"), "beta");
}

TEST_F(OutputFileTest, ReplacesTheFilesOfAnEarlierRun) {
  writeFilesAtomically(dir_, {{"a.txt", "old a"}, {"b.txt", "old b"}});
  writeFilesAtomically(dir_, {{"a.txt", "new a"}, {"b.txt", "new b"}});
  EXPECT_EQ(entries(), (std::set<std::string>{"a.txt", "b.txt"}));
  EXPECT_EQ(contentsOf(dir_ / "a.txt"), "new a");
  EXPECT_EQ(contentsOf(dir_ / "b.txt"), "new b");
}

// A name of the set taken by a directory (or a FIFO, a device) is refused before anything is
// written: the earlier run's files stay as they were.
TEST_F(OutputFileTest, ANameTakenByADirectoryOrFifoIsRefusedBeforeWriting) {
  fs::create_directories(dir_ / "b.txt");
  put(dir_ / "a.txt", "old a");
  EXPECT_NE(messageOf([&] {
              writeFilesAtomically(dir_, {{"a.txt", "new a"}, {"b.txt", "new b"}});
            }).find("b.txt: exists and is a directory"),
            std::string::npos);
  EXPECT_EQ(entries(), (std::set<std::string>{"a.txt", "b.txt"}));
  EXPECT_EQ(contentsOf(dir_ / "a.txt"), "old a");
  fs::remove(dir_ / "b.txt");
  ASSERT_EQ(::mkfifo((dir_ / "b.txt").c_str(), 0600), 0);
  EXPECT_NE(messageOf([&] {
              writeFilesAtomically(dir_, {{"a.txt", "new a"}, {"b.txt", "new b"}});
            }).find("b.txt: exists and is a FIFO"),
            std::string::npos);
  EXPECT_EQ(contentsOf(dir_ / "a.txt"), "old a");
  EXPECT_TRUE(fs::is_fifo(dir_ / "b.txt"));
}

TEST_F(OutputFileTest, AFailedWriteRemovesTheDirectoryItMade) {
  // A name with a missing subdirectory cannot be written: the failure comes after the first file.
  EXPECT_THROW(writeFilesAtomically(dir_, {{"a.txt", "alpha"}, {"missing/b.txt", "beta"}}), Error);
  EXPECT_FALSE(fs::exists(dir_));
}

TEST_F(OutputFileTest, AFailedWriteLeavesAnExistingDirectoryAsItWas) {
  fs::create_directories(dir_);
  put(dir_ / "a.txt", "old a");
  EXPECT_THROW(writeFilesAtomically(dir_, {{"a.txt", "new a"}, {"missing/b.txt", "beta"}}), Error);
  EXPECT_EQ(entries(), (std::set<std::string>{"a.txt"}));
  EXPECT_EQ(contentsOf(dir_ / "a.txt"), "old a");
}

// Files of the earlier set that the new one leaves out go with it (the preparer's level sources of
// depths a rerun does not make); what is not a regular file is never touched.
TEST_F(OutputFileTest, ObsoleteFilesOfTheEarlierSetAreTakenOutWithIt) {
  writeFilesAtomically(dir_, {{"a.txt", "old a"}, {"b.txt", "old b"}, {"c.txt", "old c"}});
  ASSERT_EQ(::mkfifo((dir_ / "fifo.txt").c_str(), 0600), 0);
  writeFilesAtomically(dir_, {{"a.txt", "new a"}}, {"b.txt", "c.txt", "absent.txt", "fifo.txt"});
  EXPECT_EQ(entries(), (std::set<std::string>{"a.txt", "fifo.txt"}));
  EXPECT_EQ(contentsOf(dir_ / "a.txt"), "new a");
}

// A failure while writing, or while taking the obsolete files out, leaves the earlier set whole.
TEST_F(OutputFileTest, AFailureKeepsTheObsoleteFilesOfTheEarlierSet) {
  writeFilesAtomically(dir_, {{"a.txt", "old a"}, {"b.txt", "old b"}});
  fs::create_directories(dir_ / "sub");
  put(dir_ / "sub" / "c.txt", "old c");
  EXPECT_THROW(writeFilesAtomically(dir_, {{"a.txt", "new a"}, {"missing/x.txt", "x"}}, {"b.txt"}),
               Error);
  EXPECT_EQ(entries(), (std::set<std::string>{"a.txt", "b.txt", "sub"}));
  // b.txt is taken out first; sub/c.txt cannot be moved aside (no "sub" among the displaced
  // files), so everything is put back.
  EXPECT_THROW(writeFilesAtomically(dir_, {{"a.txt", "new a"}}, {"b.txt", "sub/c.txt"}), Error);
  EXPECT_EQ(entries(), (std::set<std::string>{"a.txt", "b.txt", "sub"}));
  EXPECT_EQ(contentsOf(dir_ / "a.txt"), "old a");
  EXPECT_EQ(contentsOf(dir_ / "b.txt"), "old b");
  EXPECT_EQ(contentsOf(dir_ / "sub" / "c.txt"), "old c");
}

// A run killed with SIGKILL leaves its staging folder; the next run removes it (its process is
// gone), but never the folder of a writer that still runs.
TEST_F(OutputFileTest, StagingFoldersOfDeadWritersAreRemoved) {
  fs::create_directories(dir_);
  const pid_t child = ::fork();
  if (child == 0) _exit(0);
  ASSERT_GT(child, 0);
  ASSERT_EQ(::waitpid(child, nullptr, 0), child);  // its process id is now free
  const std::string dead = std::string(kStagingPrefix) + std::to_string(child);
  const std::string alive = std::string(kStagingPrefix) + "1";  // init never writes here, but lives
  fs::create_directories(dir_ / dead / "displaced");
  fs::create_directories(dir_ / alive);
  writeFilesAtomically(dir_, {{"a.txt", "alpha"}});
  EXPECT_EQ(entries(), (std::set<std::string>{"a.txt", alive}));
}

// A termination signal while the set is written: the writer stops, cleans up and the process then
// ends by that signal; the directory holds the earlier set and no staging folder. The signal is
// raised inside an outer hold so that it lands at a known point, before the first file.
TEST_F(OutputFileTest, ASignalWhileWritingLeavesTheEarlierSetAndEndsTheProcess) {
  writeFilesAtomically(dir_, {{"a.txt", "old a"}, {"b.txt", "old b"}});
  const pid_t child = ::fork();
  if (child == 0) {
    {
      const TerminationSignalsHeld held;
      ::raise(SIGTERM);
      if (TerminationSignalsHeld::interrupted() != SIGTERM) _exit(2);
      try {
        writeFilesAtomically(dir_, {{"a.txt", "new a"}, {"b.txt", "new b"}});
        _exit(3);  // it must not complete
      } catch (const Error&) {
      }
    }  // the hold ends: SIGTERM is raised again and ends the process here
    _exit(4);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "exit status " << WEXITSTATUS(status);
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_EQ(entries(), (std::set<std::string>{"a.txt", "b.txt"}));
  EXPECT_EQ(contentsOf(dir_ / "a.txt"), "old a");
  EXPECT_EQ(contentsOf(dir_ / "b.txt"), "old b");
}

TEST_F(OutputFileTest, OneFileIsWrittenWholeAndThroughASymlinkOntoItsTarget) {
  fs::create_directories(dir_);
  writeFileAtomically(dir_ / "x.png", "first");
  EXPECT_EQ(contentsOf(dir_ / "x.png"), "first");
  writeFileAtomically(dir_ / "x.png", "second");
  EXPECT_EQ(contentsOf(dir_ / "x.png"), "second");
  fs::create_symlink("x.png", dir_ / "link.png");
  writeFileAtomically(dir_ / "link.png", "third");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir_ / "link.png")));
  EXPECT_EQ(contentsOf(dir_ / "x.png"), "third");
  EXPECT_EQ(entries(), (std::set<std::string>{"x.png", "link.png"}));
}

TEST_F(OutputFileTest, OutputsThatAreNotRegularFilesAreRefusedAndKept) {
  fs::create_directories(dir_ / "sub");
  ASSERT_EQ(::mkfifo((dir_ / "fifo.png").c_str(), 0600), 0);
  fs::create_symlink("nowhere", dir_ / "dangling.png");
  fs::create_symlink("loop_b", dir_ / "loop_a");
  fs::create_symlink("loop_a", dir_ / "loop_b");
  EXPECT_NE(messageOf([] {
              writeFileAtomically("/dev/null", "x");
            }).find("/dev/null: exists and is a character device"),
            std::string::npos);
  EXPECT_NE(messageOf([&] { writeFileAtomically(dir_ / "fifo.png", "x"); }).find("is a FIFO"),
            std::string::npos);
  EXPECT_NE(messageOf([&] { writeFileAtomically(dir_ / "sub", "x"); }).find("is a directory"),
            std::string::npos);
  EXPECT_NE(messageOf([&] {
              writeFileAtomically(dir_ / "dangling.png", "x");
            }).find("dangling symbolic link"),
            std::string::npos);
  EXPECT_NE(messageOf([&] { writeFileAtomically(dir_ / "loop_a", "x"); }).find("symlink loop"),
            std::string::npos);
  EXPECT_NE(messageOf([&] {
              writeFileAtomically(dir_ / "missing" / "x.png", "x");
            }).find("does not exist"),
            std::string::npos);
  EXPECT_TRUE(fs::is_fifo(dir_ / "fifo.png"));
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  EXPECT_EQ(entries(),
            (std::set<std::string>{"sub", "fifo.png", "dangling.png", "loop_a", "loop_b"}));
}

// An output directory that is a file, a FIFO or a device is named by its kind, before anything
// is written, and stays what it was.
TEST_F(OutputFileTest, AnOutputDirectoryThatIsNotADirectoryIsNamedByItsKind) {
  fs::create_directories(dir_);
  put(dir_ / "file", "text");
  ASSERT_EQ(::mkfifo((dir_ / "fifo").c_str(), 0600), 0);
  fs::create_symlink("loop_b", dir_ / "loop_a");
  fs::create_symlink("loop_a", dir_ / "loop_b");
  fs::create_symlink("nowhere", dir_ / "dangling");
  EXPECT_EQ(messageOf([&] {
              writeFilesAtomically(dir_ / "file", {{"a.txt", "a"}});
            }),
            (dir_ / "file").string() + ": exists and is not a directory: it is a regular file");
  EXPECT_EQ(
      messageOf([&] {
        writeFilesAtomically(dir_ / "fifo", {{"a.txt", "a"}});
      }),
      (dir_ / "fifo").string() + ": exists and is not a directory: it is a FIFO (named pipe)");
  EXPECT_EQ(messageOf([] { checkOutputDirectory("/dev/null"); }),
            "/dev/null: exists and is not a directory: it is a character device");
  EXPECT_NE(messageOf([&] { checkOutputDirectory(dir_ / "loop_a"); }).find("symlink loop"),
            std::string::npos);
  EXPECT_NE(
      messageOf([&] { checkOutputDirectory(dir_ / "dangling"); }).find("dangling symbolic link"),
      std::string::npos);
  EXPECT_NO_THROW(checkOutputDirectory(dir_ / "not_yet"));
  EXPECT_NO_THROW(checkOutputDirectory(dir_));
  EXPECT_TRUE(fs::is_fifo(dir_ / "fifo"));
  EXPECT_EQ(contentsOf(dir_ / "file"), "text");
  EXPECT_EQ(entries(), (std::set<std::string>{"file", "fifo", "loop_a", "loop_b", "dangling"}));
}

}  // namespace
}  // namespace octopoint::cli
