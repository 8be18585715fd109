// octopoint-render --url end to end against tests/support/hostile_server.h: for every lie, exit 1
// with one line on stderr, no output file, within 3 s when the lie is not slowness, and bounded
// peak memory (the child's maximum resident size, from wait4); for an honest server (the default
// model, and one smaller than the first request's 4 KiB), exit 0 and the picture.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "octopoint/models.h"
#include "octopoint/progressive.h"
#include "tests/support/hostile_server.h"
#include "tests/support/model_images.h"
#include "tests/support/net_test_support.h"

namespace octopoint {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;
using Clock = std::chrono::steady_clock;
using testing::HostileOptions;
using testing::HostileServer;
using testing::Lie;

const Bytes& modelImage() { return testing::streamedModelImage(); }

struct RenderRun {
  int exit_code = -1;  // or 128 + the signal
  std::string err;
  Clock::duration took{};
  long peak_megabytes = 0;
  bool output_exists = false;
};

RenderRun render(const std::string& url, const std::vector<std::string>& more = {}) {
  testing::TempFolder folder;
  const std::string output = (folder.path() / "out.png").string();
  const std::string err_path = (folder.path() / "err.txt").string();
  std::vector<std::string> args = {OCTOPOINT_RENDER, "--url", url, "-o", output};
  args.insert(args.end(), more.begin(), more.end());
  const Clock::time_point start = Clock::now();
  const pid_t child = ::fork();
  if (child == 0) {
    const int err = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(err, 2);
    ::dup2(null, 1);
    std::vector<char*> argv;
    for (std::string& arg : args) argv.push_back(arg.data());
    argv.push_back(nullptr);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  RenderRun run;
  int status = 0;
  rusage usage{};
  while (::wait4(child, &status, WNOHANG, &usage) == 0) {
    if (Clock::now() - start > 60s) ::kill(child, SIGKILL);  // a hang: fails below
    std::this_thread::sleep_for(5ms);
  }
  run.took = Clock::now() - start;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  run.peak_megabytes = usage.ru_maxrss / 1024;
  std::ifstream err(err_path);
  std::stringstream text;
  text << err.rdbuf();
  run.err = text.str();
  run.output_exists = std::filesystem::exists(output);
  return run;
}

void expectRefusal(const RenderRun& run, const std::string& what, const std::string& says,
                   Clock::duration within) {
  EXPECT_EQ(run.exit_code, 1) << what << ": " << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << what << ": " << run.err;
  EXPECT_NE(run.err.find(says), std::string::npos) << what << ": " << run.err;
  EXPECT_FALSE(run.output_exists) << what;
  EXPECT_LT(run.took, within) << what;
  EXPECT_LT(run.peak_megabytes, 200) << what << ": MB";
}

std::uint64_t afterHead() {
  return ProgressiveModel::fromHead(modelImage(), nullptr)->head().levels[1].chunks_offset;
}

TEST(RenderUrl, RefusesEveryLieWithOneLineAndExit1Within3Seconds) {
  const std::uint64_t chunks = afterHead();
  const std::vector<std::tuple<const char*, HostileOptions, const char*>> cases = {
      {"100 KB status line", {Lie::kLongStatus, 100'000}, "status line longer than 8192"},
      {"endless status line", {Lie::kEndlessStatus}, "status line longer"},
      {"10 MB header", {Lie::kLongHeader, 10'000'000}, "header line longer than 8192"},
      {"endless header", {Lie::kEndlessHeader}, "header line longer"},
      {"many headers", {Lie::kManyHeaders, 100'000}, "more than 100 header fields"},
      {"500", {Lie::kStatus, 500}, "answered 500"},
      {"500 after the head", {Lie::kStatus, 500, chunks}, "answered 500"},
      {"301", {Lie::kRedirect}, "redirect"},
      {"416", {Lie::kStatus, 416}, "answered 416"},
      {"wrong Content-Range start", {Lie::kWrongOffset}, "Content-Range"},
      {"wrong Content-Range after the head", {Lie::kWrongEnd, 0, chunks}, "Content-Range"},
      {"Content-Range total", {Lie::kWrongTotal}, "changed"},
      {"Content-Range total after the head", {Lie::kWrongTotal, 0, chunks}, "changed"},
      {"truncated head body", {Lie::kTruncatedBody, 100}, "closed the connection"},
      {"truncated chunk", {Lie::kTruncatedBody, 7, chunks}, "closed the connection"},
      {"reset", {Lie::kReset, 50}, "reset"},
      {"closed mid-head", {Lie::kCloseMidHead, 20}, "in the middle of the response head"},
      {"damaged chunks", {Lie::kDamage, 0, chunks}, "damaged 3 times"},
      {"chunked encoding", {Lie::kChunkedEncoding}, "Transfer-Encoding"},
  };
  for (const auto& [what, options, says] : cases) {
    HostileServer server(modelImage(), options);
    expectRefusal(render(server.url()), what, says, 3s);
  }
}

TEST(RenderUrl, ARefusedConnectionIsReportedAtOnce) {
  std::string url;
  {
    HostileServer gone(modelImage(), {});
    url = gone.url();
  }  // nothing listens there now
  expectRefusal(render(url), "refused", "connection refused", 3s);
}

TEST(RenderUrl, SilenceAndTrickleEndAtTheTimeout) {
  for (const HostileOptions& options :
       {HostileOptions{Lie::kSilence}, HostileOptions{Lie::kTrickle, 300}}) {
    HostileServer server(modelImage(), options);
    expectRefusal(render(server.url(), {"--timeout", "2"}), "slow", "head did not arrive", 4s);
  }
}

TEST(RenderUrl, DrawsFromAnHonestServerAndAModelSmallerThanTheFirstRequest) {
  const Bytes tiny = fuzzing::chunkedImage(*models::defaultModel(), {3, 4}, {256, 1024});
  ASSERT_LT(tiny.size(), 4096u);
  for (const Bytes* file : {&modelImage(), &tiny}) {
    HostileServer server(*file, {});
    const RenderRun run = render(server.url());
    EXPECT_EQ(run.exit_code, 0) << file->size() << " bytes: " << run.err;
    EXPECT_TRUE(run.output_exists) << file->size() << " bytes";
    EXPECT_EQ(run.err, "");
  }
}

}  // namespace
}  // namespace octopoint
