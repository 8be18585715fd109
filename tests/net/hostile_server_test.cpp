// The client against a server that lies in every way tests/support/hostile_server.h knows:
// RangeClient must refuse each lie at once (never waiting out a timeout for anything but
// slowness), say in words what the server did, and hold no more memory than its limits allow;
// the response-head parser must hold its limits at their exact bounds, fed whole or byte by byte.
#include "tests/support/hostile_server.h"

#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <fstream>

#include "net/http_response.h"
#include "octopoint/http.h"
#include "tests/support/net_test_support.h"

namespace octopoint {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;
using Clock = std::chrono::steady_clock;
using testing::HostileOptions;
using testing::HostileServer;
using testing::Lie;

// The process's peak resident memory so far, in MB (VmHWM).
long peakMegabytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.starts_with("VmHWM:")) return std::stol(line.substr(6)) / 1024;
  return -1;
}

struct Fetched {
  net::FetchResult result;
  std::uint64_t delivered = 0;
  Clock::duration took{};
};

Fetched fetchFrom(const std::string& url, std::uint64_t offset, std::uint64_t size,
                  const net::RangeTimeouts& timeouts) {
  net::RangeClient client(*net::parseHttpUrl(url, nullptr), timeouts);
  Fetched fetched;
  const Clock::time_point start = Clock::now();
  fetched.result = client.fetch(offset, size, [&](std::uint64_t, std::span<const std::uint8_t> p) {
    fetched.delivered += p.size();
    return true;
  });
  fetched.took = Clock::now() - start;
  return fetched;
}

struct LieCase {
  const char* what;
  HostileOptions options;
  net::FetchStatus expected;
  const char* says;  // a part of the message
};

std::vector<LieCase> everyLie() {
  using S = net::FetchStatus;
  return {
      {"a 10 KB status line", {Lie::kLongStatus, 10'000}, S::kBadResponse, "status line longer"},
      {"a 100 KB status line", {Lie::kLongStatus, 100'000}, S::kBadResponse, "longer than 8192"},
      {"a 1 MB status line", {Lie::kLongStatus, 1'000'000}, S::kBadResponse, "status line"},
      {"an endless status line", {Lie::kEndlessStatus}, S::kBadResponse, "status line longer"},
      {"a header line past 8 KiB", {Lie::kLongHeader, 8'200}, S::kBadResponse, "header line"},
      {"a 10 MB header line", {Lie::kLongHeader, 10'000'000}, S::kBadResponse, "header line"},
      {"an endless header line", {Lie::kEndlessHeader}, S::kBadResponse, "header line longer"},
      {"101 header fields", {Lie::kManyHeaders, 99}, S::kBadResponse, "more than 100 header"},
      {"100,000 header fields", {Lie::kManyHeaders, 100'000}, S::kBadResponse, "more than 100"},
      {"a 500", {Lie::kStatus, 500}, S::kHttpStatus, "answered 500"},
      {"a 503", {Lie::kStatus, 503}, S::kHttpStatus, "answered 503"},
      {"a 416", {Lie::kStatus, 416}, S::kHttpStatus, "answered 416"},
      {"a 404", {Lie::kStatus, 404}, S::kHttpStatus, "answered 404"},
      {"a 200 (the whole file) to a range", {Lie::kStatus, 200}, S::kHttpStatus, "whole file"},
      {"a 301 redirect", {Lie::kRedirect}, S::kHttpStatus, "redirect to 'http://127.0.0.1:1"},
      {"a Content-Range a byte late", {Lie::kWrongOffset}, S::kBadResponse, "Content-Range"},
      {"a Content-Range a byte short", {Lie::kWrongEnd}, S::kBadResponse, "Content-Range"},
      {"a garbage Content-Range", {Lie::kGarbageRange}, S::kBadResponse, "bytes garbage"},
      {"a Content-Length one short", {Lie::kShortLength}, S::kBadResponse, "Content-Length"},
      {"a Content-Length one long", {Lie::kLongLength}, S::kBadResponse, "Content-Length"},
      {"a body cut at 0", {Lie::kTruncatedBody, 0}, S::kTooShort, "after 0 of 4000"},
      {"a body cut at 1", {Lie::kTruncatedBody, 1}, S::kTooShort, "after 1 of 4000"},
      {"a body cut at 2000", {Lie::kTruncatedBody, 2000}, S::kTooShort, "closed the connection"},
      {"a body cut at 3999", {Lie::kTruncatedBody, 3999}, S::kTooShort, "after 3999 of 4000"},
      {"a body one byte long", {Lie::kOverlongBody, 1}, S::kTooLong, "more than the 4000"},
      {"a body 1 MB long", {Lie::kOverlongBody, 1'000'000}, S::kTooLong, "more than the 4000"},
      {"a close before the head", {Lie::kCloseMidHead, 0}, S::kConnectionFailed, "without"},
      {"a close in the status line", {Lie::kCloseMidHead, 10}, S::kConnectionFailed, "middle"},
      {"a close in the headers", {Lie::kCloseMidHead, 40}, S::kConnectionFailed, "middle"},
      {"a reset before the body", {Lie::kReset, 0}, S::kTooShort, "reset"},
      {"a reset in the body", {Lie::kReset, 1000}, S::kTooShort, "reset"},
      {"a chunked body", {Lie::kChunkedEncoding}, S::kBadResponse, "Transfer-Encoding"},
      {"silence", {Lie::kSilence}, S::kTooSlow, "no byte for 1 s"},
      {"a trickle of a byte per 50 ms",
       {Lie::kTrickle, 50},
       S::kTooSlow,
       "no complete response head"},
  };
}

TEST(HostileServer, EveryLieIsRefusedAtOnceInWordsWithBoundedMemory) {
  net::RangeTimeouts timeouts;
  timeouts.read_seconds = 1;             // silence: the only case that waits, this long
  timeouts.min_bytes_per_second = 4000;  // the trickle: cut off after 1 s + 4000 B / 4000 B/s
  for (const LieCase& c : everyLie()) {
    HostileServer server(testing::streamedModelImage(), c.options);
    const Fetched fetched = fetchFrom(server.url(), 1000, 4000, timeouts);
    const std::string& message = fetched.result.message;
    EXPECT_EQ(fetched.result.status, c.expected) << c.what << ": " << message;
    EXPECT_NE(message.find(c.says), std::string::npos) << c.what << ": " << message;
    EXPECT_LE(fetched.delivered, 4000u) << c.what;
    EXPECT_EQ(message.find('\n'), std::string::npos) << c.what;
    EXPECT_LE(message.size(), 400u) << c.what << ": " << message;
    EXPECT_LT(fetched.took, c.expected == net::FetchStatus::kTooSlow ? 2500ms : 500ms) << c.what;
  }
  // The endless lines, the 10 MB header and the 1 MB body held no more than the client's
  // buffers: 64 KiB of head, 16 KiB of reading (httplib grew to over a GB).
  EXPECT_LT(peakMegabytes(), 120) << "MB at the peak";
}

TEST(HostileServer, WhatIsWithinTheLimitsIsTaken) {
  for (const HostileOptions& options :
       {HostileOptions{Lie::kNone}, HostileOptions{Lie::kLongStatus, 8'000},
        HostileOptions{Lie::kLongHeader, 8'000}, HostileOptions{Lie::kManyHeaders, 98}}) {
    HostileServer server(testing::streamedModelImage(), options);
    const Fetched fetched = fetchFrom(server.url(), 1000, 4000, {});
    EXPECT_EQ(fetched.result.status, net::FetchStatus::kOk)
        << static_cast<int>(options.lie) << " " << options.size << ": " << fetched.result.message;
    EXPECT_EQ(fetched.delivered, 4000u);
  }
}

TEST(HostileServer, ARangeCutAtTheFilesEndIsTakenAndOnlyThere) {
  HostileServer server(testing::streamedModelImage(), {});
  const std::uint64_t size = testing::streamedModelImage().size();
  for (const std::uint64_t before_end : {1u, 100u, 4095u}) {
    const Fetched fetched = fetchFrom(server.url(), size - before_end, 4096, {});
    EXPECT_EQ(fetched.result.status, net::FetchStatus::kOk) << fetched.result.message;
    EXPECT_EQ(fetched.delivered, before_end);
    EXPECT_EQ(fetched.result.file_size, size);
  }
  // Past the end: the server's 416, at once.
  const Fetched past = fetchFrom(server.url(), size, 10, {});
  EXPECT_EQ(past.result.status, net::FetchStatus::kHttpStatus) << past.result.message;
}

TEST(HostileServer, ARefusedConnectionIsReportedAtOnce) {
  // A port that was free a moment ago: nothing listens there.
  const int probe = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(probe, reinterpret_cast<sockaddr*>(&address), sizeof address);
  socklen_t length = sizeof address;
  ::getsockname(probe, reinterpret_cast<sockaddr*>(&address), &length);
  ::close(probe);
  const std::string url = "http://127.0.0.1:" + std::to_string(ntohs(address.sin_port)) + "/m.oct";
  const Fetched fetched = fetchFrom(url, 0, 100, {});
  EXPECT_EQ(fetched.result.status, net::FetchStatus::kConnectionFailed);
  EXPECT_NE(fetched.result.message.find("connection refused"), std::string::npos)
      << fetched.result.message;
  EXPECT_LT(fetched.took, 500ms);
}

// The stream, as octopoint-render runs it (give_up_after 3): a server that lies after an honest
// head fails the stream within a second or two, saying why.
TEST(HostileServer, AStreamGivesUpOnALyingServerSoon) {
  const std::uint64_t after_head =
      ProgressiveModel::fromHead(testing::streamedModelImage(), nullptr)
          ->head()
          .levels[1]
          .chunks_offset;
  const std::vector<std::pair<HostileOptions, const char*>> cases = {
      {{Lie::kStatus, 500, after_head}, "answered 500"},
      {{Lie::kWrongTotal, 0, 0}, "changed"},
      {{Lie::kWrongTotal, 0, after_head}, "changed"},
      {{Lie::kTruncatedBody, 10, after_head}, "closed the connection"},
      {{Lie::kEndlessStatus, 0, after_head}, "status line longer"},
      {{Lie::kRedirect, 0, 0}, "redirect"},
  };
  for (const auto& [options, says] : cases) {
    HostileServer server(testing::streamedModelImage(), options);
    net::StreamOptions stream_options;
    stream_options.give_up_after = 3;
    stream_options.prefetch_invisible = false;
    net::ModelStream stream(*net::parseHttpUrl(server.url(), nullptr), stream_options);
    stream.setView(Camera{});
    const Clock::time_point start = Clock::now();
    stream.start();
    const net::StreamStatus status = stream.waitUntilSettled(20s);
    EXPECT_TRUE(status.failed) << says;
    EXPECT_NE(status.error.find(says), std::string::npos) << status.error;
    EXPECT_LT(Clock::now() - start, 3s) << says;
  }
}

// The parser alone, at its bounds, fed whole and byte by byte.
net::ResponseHeadParser::State parse(const std::string& text, bool bytewise, std::string* error) {
  net::ResponseHeadParser parser;
  if (bytewise) {
    for (std::size_t i = 0;
         i < text.size() && parser.state() == net::ResponseHeadParser::State::kNeedMore; ++i)
      parser.feed(std::string_view(text).substr(i, 1));
  } else {
    parser.feed(text);
  }
  *error = parser.error();
  return parser.state();
}

TEST(ResponseHeadParser, HoldsEachLimitAtItsBound) {
  using State = net::ResponseHeadParser::State;
  const auto status = [](std::size_t line) {
    return "HTTP/1.1 206 " + std::string(line - 13, 'r') + "\r\n\r\n";
  };
  const auto fields = [](std::size_t count, std::size_t value) {
    std::string head = "HTTP/1.1 206 OK\r\n";
    for (std::size_t i = 0; i < count; ++i)
      head += "F" + std::to_string(i) + ": " + std::string(value, 'v') + "\r\n";
    return head + "\r\n";
  };
  const std::vector<std::tuple<std::string, State, const char*>> cases = {
      {status(8192), State::kDone, ""},
      {status(8193), State::kError, "status line longer than 8192"},
      {fields(100, 10), State::kDone, ""},
      {fields(101, 10), State::kError, "more than 100 header fields"},
      {fields(1, 8192 - 4), State::kDone, ""},
      {fields(1, 8192 - 3), State::kError, "header line longer than 8192"},
      {fields(8, 8000), State::kDone, ""},
      {fields(9, 8000), State::kError, "head longer than 65536"},
      {"HTTP/2 200 OK\r\n\r\n", State::kError, "not an HTTP/1.x status line"},
      {"HTTP/1.1 20 OK\r\n\r\n", State::kError, "not an HTTP/1.x"},
      {"HTTP/1.1 206 OK\r\n folded\r\n\r\n", State::kError, "malformed header"},
      {"HTTP/1.1 206 OK\r\nno colon\r\n\r\n", State::kError, "malformed header"},
  };
  for (const auto& [text, expected, says] : cases) {
    for (const bool bytewise : {false, true}) {
      std::string error;
      EXPECT_EQ(parse(text, bytewise, &error), expected) << text.substr(0, 60) << ": " << error;
      EXPECT_NE(error.find(says), std::string::npos) << error;
    }
  }
}

TEST(ResponseHeadParser, ReadsContentRangeStrictly) {
  std::uint64_t first = 0, last = 0, total = 0;
  EXPECT_TRUE(net::parseContentRange("bytes 0-9/10", &first, &last, &total));
  EXPECT_EQ(total, 10u);
  EXPECT_TRUE(net::parseContentRange("bytes 5-9/*", &first, &last, &total));
  EXPECT_EQ(total, 0u);
  for (const char* lie : {"bytes 0-10/10", "bytes 9-5/10", "bytes -1-5/10", "bytes 0-5/10x",
                          "bytes 0-5", "items 0-5/10", "bytes 0-99999999999999999999/1", ""})
    EXPECT_FALSE(net::parseContentRange(lie, &first, &last, &total)) << lie;
}

}  // namespace
}  // namespace octopoint
