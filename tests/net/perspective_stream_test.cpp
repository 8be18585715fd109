// net::ModelStream following a perspective view (renderer/perspective_fetch.h's order): with no
// view it fetches the head alone; with a view it settles once that view is complete, having
// fetched no depth the view does not ask for (from afar, not the finest), and the parts it holds
// then draw the whole file's frame, bit for bit.
#include <gtest/gtest.h>

#include <chrono>

#include "codegen/chunked_writer.h"
#include "octopoint/framebuffer.h"
#include "octopoint/http.h"
#include "octopoint/models.h"
#include "renderer/chunked_assembly.h"
#include "renderer/perspective.h"
#include "renderer/perspective_renderer.h"
#include "tests/support/model_images.h"
#include "tests/support/net_test_support.h"

namespace octopoint {
namespace {

using namespace std::chrono_literals;

// The eye at the table's edge looking down, or 2.5 cube edges away (depth 8 spans under a pixel).
PerspectiveView streamedView(bool far) {
  PerspectiveCamera camera;
  camera.eye = far ? ModelPoint{0, 0, -kPerspectiveUnit * 5 / 2}
                   : ModelPoint{kPerspectiveUnit / 20, -kPerspectiveUnit / 5,
                                -kPerspectiveUnit * 2 / 5};
  camera.pitch = Angle::fromDegrees(far ? 0 : -20);
  camera.width = 320;
  camera.height = 240;
  PerspectiveView view;
  EXPECT_EQ(buildPerspectiveView(camera, kDefaultFractionBits, &view), PerspectiveError::kNone);
  return view;
}

void drawHeld(const HeldParts& parts, const PerspectiveView& view, Framebuffer& frame) {
  frame.clear();
  for (const std::unique_ptr<AssembledModel>& part : parts.parts)
    EXPECT_TRUE(PerspectiveRenderer(*part->view, parts.detailDepths()).draw(view, {}, frame));
}

TEST(PerspectiveStream, FollowsTheViewAndDrawsTheWholeFilesFrame) {
  const std::vector<std::uint8_t> image = prepare::serializeChunkedModel(
      fuzzing::preparedModel(*models::defaultModel(), {4, 5, 6, 7, 8}), {64, 600});
  const std::optional<ProgressiveModel> whole = progressiveModelFromPrefix(image, nullptr);
  ASSERT_TRUE(whole.has_value());
  const std::unique_ptr<AssembledModel> file_model = assembleChunked(*whole);
  ASSERT_NE(file_model, nullptr);
  testing::TempFolder folder;
  folder.write("model.oct", image);
  net::ServerOptions options;
  options.root = folder.path();
  options.port = 0;
  const testing::RunningServer server(options);
  for (const bool far : {false, true}) {
    SCOPED_TRACE(far ? "far" : "near");
    net::StreamOptions stream_options;
    stream_options.prefetch_invisible = false;
    net::ModelStream stream(
        *net::parseHttpUrl("http://127.0.0.1:" + std::to_string(server.port()) + "/model.oct",
                           nullptr),
        stream_options);
    stream.clearView();
    stream.start();
    const net::StreamStatus head = stream.waitUntilSettled(30s);
    ASSERT_TRUE(head.head_known) << head.error;
    EXPECT_EQ(head.chunks_held, 0u);  // no view, nothing but the head
    EXPECT_EQ(head.requests, 1u);
    const PerspectiveView view = streamedView(far);
    stream.setView(view);
    const net::StreamStatus done = stream.waitUntilSettled(60s);
    ASSERT_TRUE(done.view_complete) << done.error;
    HeldParts parts;
    int finest_held = 0;
    stream.withModel([&](ProgressiveModel* model) {
      parts = assembleHeldParts(*model);
      for (int level = 1; level < model->levelCount(); ++level) {
        for (std::uint32_t i = 0; i < model->chunkCount(level); ++i) {
          if (model->chunkState(level, i) == ChunkState::kHeld) finest_held = level;
        }
      }
    });
    // From afar depth 8 (level 5; level 0 is the head's base) is finer than any pixel.
    EXPECT_EQ(finest_held, far ? 4 : 5);
    if (far) {
      EXPECT_LT(done.bytes_received * 2, image.size());
    }
    Framebuffer from_stream(320, 240), from_file(320, 240);
    drawHeld(parts, view, from_stream);
    from_file.clear();
    PerspectiveDrawStats stats;
    ASSERT_TRUE(PerspectiveRenderer(*file_model->view).draw(view, {}, from_file, &stats));
    EXPECT_GT(stats.leaves, 1000u);
    EXPECT_TRUE(std::equal(from_stream.pixels().begin(), from_stream.pixels().end(),
                           from_file.pixels().begin()));
  }
}

}  // namespace
}  // namespace octopoint
