// The output folder swap (cli/folder_swap.h): SIGKILL, which no handler sees, at any moment of
// writeFilesAtomically leaves the old set or the new one in the folder, never a mix, and the next
// run removes what the killed one left beside it.
#include "cli/folder_swap.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli/output_file.h"

namespace octopoint::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr int kFiles = 64;  // 128 renames one by one: a window a kill sweep finds

std::vector<OutputFile> setOf(const std::string& generation) {
  std::vector<OutputFile> files;
  for (int i = 0; i < kFiles; ++i) {
    files.push_back({"f" + std::to_string(i) + ".bin", generation + std::string(4 * 1024, 'x')});
  }
  return files;
}

// "old", "new" or "mixed" (or "missing"): what the visible files of the folder hold.
std::string generationIn(const fs::path& folder) {
  std::map<std::string, int> seen;
  int visible = 0;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.path().filename().string().starts_with(".")) continue;  // a staging folder
    ++visible;
    std::ifstream in(entry.path(), std::ios::binary);
    std::string head(3, '\0');
    in.read(head.data(), 3);
    ++seen[head];
  }
  if (visible != kFiles) return "missing";
  return seen.size() == 1 ? seen.begin()->first : "mixed";
}

// Starts writing the new set in a child and kills it with SIGKILL after `delay`.
void killWriterAfter(const fs::path& folder, Clock::duration delay) {
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    try {
      writeFilesAtomically(folder, setOf("new"));
    } catch (...) {
      ::_exit(1);
    }
    ::_exit(0);
  }
  std::this_thread::sleep_for(delay);
  ::kill(child, SIGKILL);
  int status = 0;
  ::waitpid(child, &status, 0);
}

TEST(FolderSwap, SigkillAtAnyMomentLeavesTheOldSetOrTheNew) {
  const fs::path folder =
      fs::temp_directory_path() / ("octopoint_folder_swap_" + std::to_string(::getpid()));
  fs::remove_all(folder);
  fs::create_directories(folder);
  const Clock::time_point start = Clock::now();
  writeFilesAtomically(folder, setOf("new"));
  const Clock::duration one_write = Clock::now() - start;
  std::map<std::string, int> outcomes;
  constexpr int kKills = 100;
  for (int k = 0; k < kKills; ++k) {
    writeFilesAtomically(folder, setOf("old"));
    // From before the child starts writing to well past the end of its write.
    killWriterAfter(folder, one_write * 2 * k / kKills);
    ++outcomes[generationIn(folder)];
  }
  EXPECT_EQ(outcomes["mixed"], 0);
  EXPECT_EQ(outcomes["missing"], 0);
  EXPECT_GT(outcomes["old"], 0) << "no kill came before the swap";
  // The next run removes what the killed ones left: no sibling, no staging folder.
  writeFilesAtomically(folder, setOf("new"));
  EXPECT_EQ(generationIn(folder), "new");
  const std::string sibling_prefix = "." + folder.filename().string() + std::string(kSwapInfix);
  for (const auto& entry : fs::directory_iterator(folder.parent_path())) {
    EXPECT_FALSE(entry.path().filename().string().starts_with(sibling_prefix)) << entry.path();
  }
  for (const auto& entry : fs::directory_iterator(folder)) {
    EXPECT_FALSE(entry.path().filename().string().starts_with(".")) << entry.path();
  }
  fs::remove_all(folder);
}

}  // namespace
}  // namespace octopoint::cli
