// A byte budget (`octopoint-render --url URL --bytes N`, StreamOptions::byte_budget) can end
// anywhere: inside the head, inside the first requests, between chunks or past the file's end. At
// every cut the stream must settle at once, with what its bytes give: a plan that asks for nothing
// while the budget is not spent once made the stream plan again for ever, holding its lock (this
// test then waited for ctest's timeout). Every 13th cut of a small two-depth chunked model, served
// by octopoint-serve's server in this process (the end-to-end run through octopoint-render is
// net.render_bytes_sweep, on fewer cuts).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "octopoint/http.h"
#include "octopoint/models.h"
#include "tests/support/model_images.h"
#include "tests/support/net_test_support.h"

namespace octopoint {
namespace {

using namespace std::chrono_literals;

TEST(ByteBudget, EveryCutOfASmallModelSettlesAtOnceWithinItsBytes) {
  // Two stored depths and a handful of chunks: its first requests are small, so that cuts fall
  // inside them (the default model's are larger than most budgets tried).
  const std::vector<std::uint8_t> image = fuzzing::chunkedImage(*models::defaultModel(), {4, 6});
  ASSERT_LT(image.size(), 64'000u);
  testing::TempFolder folder;
  folder.write("small.oct", image);
  net::ServerOptions server_options;
  server_options.root = folder.path();
  server_options.port = 0;
  testing::RunningServer server(server_options);
  const net::HttpUrl url = *net::parseHttpUrl(
      "http://127.0.0.1:" + std::to_string(server.port()) + "/small.oct", nullptr);
  const Camera camera;
  int drawable = 0;
  // Every 13 bytes from 1 to past the end: cuts at many offsets within every request.
  for (std::uint64_t budget = 1; budget < image.size() + 300; budget += 13) {
    SCOPED_TRACE("--bytes " + std::to_string(budget));
    net::StreamOptions options;  // as octopoint-render --bytes sets them (tools/chunked_render.cpp)
    options.byte_budget = budget;
    options.connections = 1;
    options.prefetch_invisible = false;
    options.give_up_after = 3;
    options.first_request_bytes = std::min<std::uint64_t>(budget, 4096);
    net::ModelStream stream(url, options);
    stream.setView(camera);
    stream.start();
    const auto started = std::chrono::steady_clock::now();
    const net::StreamStatus status = stream.waitUntilSettled(5s);
    const auto took = std::chrono::steady_clock::now() - started;
    stream.stop();
    ASSERT_TRUE(status.settled) << "still fetching after 5 s: " << status.requests << " requests";
    EXPECT_LT(took, 2s);  // a sound cut takes milliseconds
    EXPECT_FALSE(status.failed) << status.error;
    EXPECT_LE(status.bytes_received, budget);
    if (status.head_known) ++drawable;
  }
  EXPECT_GT(drawable, 10);
}

}  // namespace
}  // namespace octopoint
