// The client (octopoint/http.h, octopoint/http.h) against servers that lie, stall, cut off,
// talk without end, damage bytes or die: it must refuse what is wrong, never hand the model a
// damaged chunk, fetch a damaged chunk again a bounded number of times, keep what it has when the
// server goes away and resume when it comes back.
#include <gtest/gtest.h>
#include <sys/socket.h>

#include <chrono>
#include <map>
#include <mutex>
#include <thread>

#include "octopoint/http.h"
#include "tests/support/net_test_support.h"

namespace octopoint {
namespace {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;
using octopoint::testing::ScriptedServer;

net::HttpUrl urlOf(int port, const std::string& path = "/model.oct") {
  return *net::parseHttpUrl("http://127.0.0.1:" + std::to_string(port) + path, nullptr);
}

std::string slice(const Bytes& file, std::uint64_t first, std::uint64_t last) {
  return std::string(file.begin() + static_cast<std::ptrdiff_t>(first),
                     file.begin() + static_cast<std::ptrdiff_t>(last + 1));
}

// A correct answer for [first, last] of the model, last clamped to the file.
bool answerHonestly(std::uint64_t first, std::uint64_t last, int sock) {
  const Bytes& file = testing::streamedModelImage();
  last = std::min<std::uint64_t>(last, file.size() - 1);
  ScriptedServer::sendAll(
      sock, ScriptedServer::partialHeader(first, last, file.size(), last - first + 1) +
                slice(file, first, last));
  return true;
}

net::FetchResult fetchFrom(int port, std::uint64_t offset, std::uint64_t size,
                           Bytes* body = nullptr, net::RangeTimeouts timeouts = {}) {
  net::RangeClient client(urlOf(port), timeouts);
  return client.fetch(offset, size, [&](std::uint64_t, std::span<const std::uint8_t> piece) {
    if (body != nullptr) body->insert(body->end(), piece.begin(), piece.end());
    return true;
  });
}

TEST(RangeClient, TakesAnHonestAnswer) {
  ScriptedServer server(answerHonestly);
  Bytes body;
  const net::FetchResult result = fetchFrom(server.port(), 100, 50, &body);
  EXPECT_EQ(result.status, net::FetchStatus::kOk) << result.message;
  EXPECT_EQ(body, Bytes(testing::streamedModelImage().begin() + 100,
                        testing::streamedModelImage().begin() + 150));
  EXPECT_EQ(result.file_size, testing::streamedModelImage().size());
}

TEST(RangeClient, RefusesEveryWrongAnswer) {
  const Bytes& file = testing::streamedModelImage();
  struct Case {
    const char* what;
    ScriptedServer::Respond respond;
    net::FetchStatus expected;
  };
  const std::vector<Case> cases = {
      {"another range",
       [&](std::uint64_t first, std::uint64_t last, int sock) {
         ScriptedServer::sendAll(sock, ScriptedServer::partialHeader(
                                           first + 1, last + 1, file.size(), last - first + 1) +
                                           slice(file, first + 1, last + 1));
         return true;
       },
       net::FetchStatus::kBadResponse},
      {"a longer Content-Length",
       [&](std::uint64_t first, std::uint64_t last, int sock) {
         ScriptedServer::sendAll(
             sock, ScriptedServer::partialHeader(first, last, file.size(), last - first + 2) +
                       slice(file, first, last + 1));
         return true;
       },
       net::FetchStatus::kBadResponse},
      {"the whole file for a range",
       [&](std::uint64_t, std::uint64_t, int sock) {
         ScriptedServer::sendAll(
             sock, "HTTP/1.1 200 OK\r\nContent-Length: " + std::to_string(file.size()) +
                       "\r\n\r\n" + slice(file, 0, file.size() - 1));
         return true;
       },
       net::FetchStatus::kHttpStatus},
      {"an endless chunked body (Transfer-Encoding)",
       [&](std::uint64_t first, std::uint64_t last, int sock) {
         ScriptedServer::sendAll(sock, "HTTP/1.1 206 Partial Content\r\nContent-Range: bytes " +
                                           std::to_string(first) + "-" + std::to_string(last) +
                                           "/" + std::to_string(file.size()) +
                                           "\r\nTransfer-Encoding: chunked\r\n\r\n");
         const std::string piece = "400\r\n" + std::string(1024, 'x') + "\r\n";
         for (int i = 0; i < 100000; ++i) {
           if (::send(sock, piece.data(), piece.size(), MSG_NOSIGNAL) <= 0)
             break;  // the client hung up
         }
         return false;
       },
       // Refused at the head: a range has a known length, sent as Content-Length by every
       // static server; a chunked one is never read.
       net::FetchStatus::kBadResponse},
      {"a body cut short",
       [&](std::uint64_t first, std::uint64_t last, int sock) {
         ScriptedServer::sendAll(
             sock, ScriptedServer::partialHeader(first, last, file.size(), last - first + 1) +
                       slice(file, first, last - 10));
         return false;  // and close
       },
       net::FetchStatus::kTooShort},
      {"a 503",
       [&](std::uint64_t, std::uint64_t, int sock) {
         ScriptedServer::sendAll(sock,
                                 "HTTP/1.1 503 Service Unavailable\r\nContent-Length: 0\r\n\r\n");
         return true;
       },
       net::FetchStatus::kHttpStatus},
      {"nothing at all", [&](std::uint64_t, std::uint64_t, int) { return false; },
       net::FetchStatus::kConnectionFailed},
  };
  for (const Case& c : cases) {
    ScriptedServer server(c.respond);
    Bytes body;
    const net::FetchResult result = fetchFrom(server.port(), 1000, 4000, &body);
    EXPECT_EQ(result.status, c.expected) << c.what << ": " << result.message;
    EXPECT_LE(body.size(), 4000u) << c.what;
  }
}

TEST(RangeClient, GivesUpOnAStalledOrTricklingServer) {
  const Bytes& file = testing::streamedModelImage();
  ScriptedServer stall([&](std::uint64_t first, std::uint64_t last, int sock) {
    ScriptedServer::sendAll(
        sock, ScriptedServer::partialHeader(first, last, file.size(), last - first + 1) +
                  slice(file, first, first + 9));
    std::this_thread::sleep_for(3s);  // then nothing
    return false;
  });
  net::RangeTimeouts timeouts;
  timeouts.read_seconds = 1;
  const auto start = std::chrono::steady_clock::now();
  const net::FetchResult stalled = fetchFrom(stall.port(), 0, 100, nullptr, timeouts);
  EXPECT_NE(stalled.status, net::FetchStatus::kOk);
  EXPECT_LT(std::chrono::steady_clock::now() - start, 2500ms);
}

std::uint64_t firstChunkOffset() {
  static const std::uint64_t offset =
      ProgressiveModel::fromHead(testing::streamedModelImage(), nullptr)
          ->head()
          .levels[1]
          .chunks_offset;
  return offset;
}

// The stream against a server that damages bytes: every answer holding chunks (not the head or
// the record tables) damaged the first `damaged` times its item is asked for. An item is known by
// the last byte of its range: a retry of an item whose start arrived with the first request's
// bytes asks only for the part after what was known then, which is more if the first request was
// still streaming when the item was last planned, so the first byte asked for can differ between
// attempts at the same item, and counting by it damaged one item a third time (a flaky failure).
struct DamagingServer {
  explicit DamagingServer(int damaged_answers) : damaged(damaged_answers) {}
  int damaged;
  std::mutex mutex;
  std::map<std::uint64_t, int> answers;  // per last byte asked for: per item (one per request)
  ScriptedServer server{[this](std::uint64_t first, std::uint64_t last, int sock) {
    const Bytes& file = testing::streamedModelImage();
    last = std::min<std::uint64_t>(last, file.size() - 1);
    std::string body = slice(file, first, last);
    int seen = 0;
    {
      std::lock_guard<std::mutex> lock(mutex);
      seen = answers[last]++;
    }
    if (first >= firstChunkOffset() && seen < damaged) body[body.size() / 2] ^= 0x10;
    ScriptedServer::sendAll(
        sock, ScriptedServer::partialHeader(first, last, file.size(), body.size()) + body);
    return true;
  }};
};

Framebuffer drawnFrame(net::ModelStream& stream, const Camera& camera) {
  Framebuffer frame(camera.width, camera.height);
  frame.clear();
  stream.withModel([&](ProgressiveModel* model) {
    ASSERT_NE(model, nullptr);
    EXPECT_TRUE(model->draw(camera, Variant::kFixedFast, frame));
  });
  return frame;
}

Framebuffer wholeFileFrame(const Camera& camera) {
  std::optional<ProgressiveModel> whole =
      progressiveModelFromPrefix(testing::streamedModelImage(), nullptr);
  Framebuffer frame(camera.width, camera.height);
  frame.clear();
  EXPECT_TRUE(whole->draw(camera, Variant::kFixedFast, frame));
  return frame;
}

bool same(const Framebuffer& a, const Framebuffer& b) {
  return std::equal(a.pixels().begin(), a.pixels().end(), b.pixels().begin(), b.pixels().end());
}

TEST(ModelStream, FetchesADamagedChunkAgainAndEndsWithTheRightPicture) {
  DamagingServer damaging(2);  // twice damaged, then right: within the three attempts
  net::StreamOptions options;
  options.max_request_bytes = 1;  // one chunk per request, so each answer damages one chunk
  options.prefetch_invisible = false;
  net::ModelStream stream(urlOf(damaging.server.port()), options);
  const Camera camera;
  stream.setView(camera);
  stream.start();
  const net::StreamStatus status = stream.waitUntilSettled(60s);
  EXPECT_TRUE(status.view_complete);
  EXPECT_GT(status.refused_items, 0u);
  EXPECT_TRUE(same(drawnFrame(stream, camera), wholeFileFrame(camera)));
  for (const auto& [last, count] : damaging.answers) EXPECT_LE(count, 3) << "bytes up to " << last;
}

TEST(ModelStream, GivesUpOnAChunkDamagedEveryTimeAndNeverDrawsIt) {
  DamagingServer damaging(1'000'000);
  net::StreamOptions options;
  options.max_request_bytes = 1;
  options.prefetch_invisible = false;
  // The head alone in the first answer, which is not damaged: no chunk arrives whole with it.
  options.first_request_bytes =
      ProgressiveModel::fromHead(testing::streamedModelImage(), nullptr)->head().head_bytes;
  net::ModelStream stream(urlOf(damaging.server.port()), options);
  const Camera camera;
  stream.setView(camera);
  stream.start();
  const net::StreamStatus status = stream.waitUntilSettled(60s);
  EXPECT_TRUE(status.settled);
  EXPECT_FALSE(status.view_complete);
  EXPECT_EQ(status.chunks_held, 0u);
  EXPECT_GE(status.refused_items,
            static_cast<std::uint32_t>(ProgressiveModel::kMaxChunkAttempts));  // tried, refused
  for (const auto& [last, count] : damaging.answers)
    EXPECT_LE(count, ProgressiveModel::kMaxChunkAttempts);
  // What it draws is the base alone: the head, which is whole.
  std::optional<ProgressiveModel> head_only =
      ProgressiveModel::fromHead(testing::streamedModelImage(), nullptr);
  Framebuffer base(camera.width, camera.height);
  base.clear();
  EXPECT_TRUE(head_only->draw(camera, Variant::kFixedFast, base));
  EXPECT_TRUE(same(drawnFrame(stream, camera), base));
}

TEST(ModelStream, KeepsWhatItHasWhenTheServerDiesAndResumesWhenItReturns) {
  testing::TempFolder folder;
  folder.write("model.oct", testing::streamedModelImage());
  net::ServerOptions options;
  options.root = folder.path();
  options.port = 0;
  options.rate_bytes_per_second = 40'000;  // slow, so that it dies mid-transfer
  auto server = std::make_unique<testing::RunningServer>(options);
  const int port = server->port();
  net::StreamOptions stream_options;
  stream_options.prefetch_invisible = false;
  net::ModelStream stream(urlOf(port), stream_options);
  const Camera camera;
  stream.setView(camera);
  stream.start();
  while (stream.status().chunks_held < 10) std::this_thread::sleep_for(20ms);
  server.reset();  // dies, mid-transfer
  std::this_thread::sleep_for(1s);
  const net::StreamStatus down = stream.status();
  EXPECT_GE(down.chunks_held, 10u);  // kept
  EXPECT_GT(down.failed_requests, 0u);
  EXPECT_FALSE(down.view_complete);
  drawnFrame(stream, camera);  // and still draws
  options.port = port;
  options.rate_bytes_per_second = 0;
  server = std::make_unique<testing::RunningServer>(options);  // back, on the same port
  const net::StreamStatus up = stream.waitUntilSettled(60s);
  EXPECT_TRUE(up.view_complete);
  EXPECT_TRUE(same(drawnFrame(stream, camera), wholeFileFrame(camera)));
}

TEST(ModelStream, StopsForGoodWhenTheHeadIsNotAModel) {
  testing::TempFolder folder;
  folder.write("model.oct", Bytes(5000, 'x'));
  net::ServerOptions options;
  options.root = folder.path();
  options.port = 0;
  testing::RunningServer server(options);
  net::ModelStream stream(urlOf(server.port()), {});
  stream.start();
  const net::StreamStatus status = stream.waitUntilSettled(10s);
  EXPECT_TRUE(status.failed);
  EXPECT_NE(status.error.find("bad magic"), std::string::npos) << status.error;
  net::ModelStream missing(urlOf(server.port(), "/nothere.oct"), {});
  missing.start();
  EXPECT_NE(missing.waitUntilSettled(10s).error.find("404"), std::string::npos);
}

}  // namespace
}  // namespace octopoint
