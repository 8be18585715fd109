// The input-file check every tool runs before reading (cli/input_file.h): each kind of path that
// is not a regular file within the limit gets its own true message, before any byte is read.
#include "cli/input_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "cli/error.h"

namespace octopoint::cli {
namespace {

namespace fs = std::filesystem;

constexpr InputKind kScene{"scene file", 1024};

class InputFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("octopoint_input_file_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static std::string messageOf(const std::function<void()>& action) {
    try {
      action();
    } catch (const Error& error) {
      return error.what();
    }
    return "no error";
  }
  std::string readError(const fs::path& path) const {
    return messageOf([&] { readInputFile(path, kScene); });
  }

  fs::path dir_;
};

TEST_F(InputFileTest, ReadsARegularFileAlsoThroughASymlink) {
  std::ofstream(dir_ / "a.json") << "{}";
  fs::create_symlink("a.json", dir_ / "link.json");
  EXPECT_EQ(readInputFile(dir_ / "a.json", kScene), "{}");
  EXPECT_EQ(readInputFile(dir_ / "link.json", kScene), "{}");
  EXPECT_EQ(checkInputFile(dir_ / "a.json", kScene), 2u);
}

TEST_F(InputFileTest, EachKindOfNonFileHasItsOwnMessage) {
  fs::create_directories(dir_ / "folder");
  ASSERT_EQ(::mkfifo((dir_ / "fifo").c_str(), 0600), 0);
  fs::create_symlink("nowhere", dir_ / "dangling");
  fs::create_symlink("loop_b", dir_ / "loop_a");
  fs::create_symlink("loop_a", dir_ / "loop_b");
  std::ofstream(dir_ / "file") << "x";
  const std::string d = dir_.string();
  EXPECT_EQ(readError(dir_ / "missing"), d + "/missing: no such file");
  EXPECT_EQ(readError(dir_ / "folder"), d + "/folder: is a directory, not a scene file");
  // A FIFO must be refused at once, not read (which would block forever).
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(readError(dir_ / "fifo"),
            d + "/fifo: is a FIFO (named pipe), not a regular file: a scene file must be a file");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
  EXPECT_EQ(readError("/dev/zero"),
            "/dev/zero: is a character device, not a regular file: a scene file must be a file");
  EXPECT_EQ(readError(dir_ / "dangling"),
            d + "/dangling: is a dangling symbolic link (what it points to does not exist)");
  EXPECT_EQ(readError(dir_ / "loop_a"),
            d + "/loop_a: too many levels of symbolic links (a symlink loop?)");
  EXPECT_EQ(readError(dir_ / "file" / "x"), d + "/file/x: a part of the path is not a directory");
  EXPECT_EQ(messageOf([] { readInputFile("", kScene); }),
            "an empty file name was given for a scene file");
  EXPECT_EQ(messageOf([] {
              readInputFile("", {"octopoint model", 1});
            }),
            "an empty file name was given for an octopoint model");
}

TEST_F(InputFileTest, AFileOverTheLimitIsRefusedByItsSize) {
  // Sparse: 2 GiB that take no disk space, refused from its size without reading.
  { std::ofstream big(dir_ / "big.json"); }
  fs::resize_file(dir_ / "big.json", 2 * kGiB);
  EXPECT_EQ(
      messageOf([&] {
        checkInputFile(dir_ / "big.json", {"scan", kGiB});
      }),
      (dir_ / "big.json").string() + ": 2147483648 bytes, more than the 1 GiB a scan may have");
  std::ofstream(dir_ / "limit.json") << std::string(1024, ' ');
  EXPECT_EQ(readInputFile(dir_ / "limit.json", kScene).size(), 1024u);
  std::ofstream(dir_ / "over.json") << std::string(1025, ' ');
  EXPECT_EQ(
      readError(dir_ / "over.json"),
      (dir_ / "over.json").string() + ": 1025 bytes, more than the 1 KiB a scene file may have");
}

TEST(DescribeBytes, StatesLimitsInTheirUnit) {
  EXPECT_EQ(describeBytes(kGiB), "1 GiB");
  EXPECT_EQ(describeBytes(512 * kMiB), "512 MiB");
  EXPECT_EQ(describeBytes(kKiB), "1 KiB");
  EXPECT_EQ(describeBytes(1000), "1000 bytes");
}

}  // namespace
}  // namespace octopoint::cli
