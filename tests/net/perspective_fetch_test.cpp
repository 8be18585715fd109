// The fetch order of a chunked model for a perspective view (renderer/perspective_fetch.h): record
// tables first, then visible chunks coarse level before fine and nearest first within a level,
// only where detail by distance asks for the level's depth; never what is held or behind the eye;
// and the fetch planner's requests follow it, as net::ModelStream does (the stream test below).
#include "renderer/perspective_fetch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "codegen/chunked_writer.h"
#include "net/fetch_planner.h"
#include "octopoint/framebuffer.h"
#include "octopoint/http.h"
#include "octopoint/models.h"
#include "octopoint/progressive.h"
#include "renderer/chunked_assembly.h"
#include "renderer/perspective.h"
#include "renderer/perspective_renderer.h"
#include "tests/support/model_images.h"
#include "tests/support/net_test_support.h"

namespace octopoint {
namespace {

constexpr std::int64_t kFetchEdge = kPerspectiveUnit;

struct FetchFixture {
  prepare::PreparedModel prepared =
      fuzzing::preparedModel(*models::defaultModel(), {4, 5, 6, 7, 8});
  std::vector<std::uint8_t> image = prepare::serializeChunkedModel(prepared, {64, 600});
  // The head and every record table, no chunk.
  ProgressiveModel tablesOnly() const {
    ChunkedIssue issue;
    std::optional<ProgressiveModel> whole = progressiveModelFromPrefix(image, &issue);
    EXPECT_TRUE(whole.has_value());
    const std::size_t tables_end = whole->head().levels[1].chunks_offset;
    std::optional<ProgressiveModel> model =
        progressiveModelFromPrefix(std::span(image).first(tables_end), &issue);
    EXPECT_TRUE(model.has_value());
    return std::move(*model);
  }
};

// An eye at the table's edge, inside the cube, looking down at the objects; or 2.5 cube edges
// before it, where depth 8 is finer than a pixel everywhere.
PerspectiveView insideView(bool far = false) {
  PerspectiveCamera camera;
  camera.eye = far ? ModelPoint{0, 0, -kFetchEdge * 5 / 2}
                   : ModelPoint{kFetchEdge / 20, -kFetchEdge / 5, -kFetchEdge * 2 / 5};
  camera.pitch = Angle::fromDegrees(far ? 0 : -20);
  camera.width = 320;
  camera.height = 240;
  PerspectiveView view;
  EXPECT_EQ(buildPerspectiveView(camera, kDefaultFractionBits, &view), PerspectiveError::kNone);
  return view;
}

// A region's centre and its depth in the view, in double precision from the record's Morton code.
struct RegionDepth {
  double z;      // camera-space depth of the centre, cube edges
  double reach;  // half the region's edge times sqrt(3)
};
RegionDepth regionDepth(const ProgressiveModel& model, const PerspectiveView& view,
                        const FetchItem& item) {
  const int region_level = model.head().levels[static_cast<std::size_t>(item.level)].region_level;
  const std::uint32_t code = model.record(item.level, item.index).region;
  double centre[3] = {0, 0, 0};
  for (int level = 0; level < region_level; ++level) {
    const unsigned child = (code >> (3 * (region_level - 1 - level))) & 7u;
    const double step = std::ldexp(1.0, -2 - level);
    centre[0] += (child & 4u) ? step : -step;
    centre[1] += (child & 2u) ? step : -step;
    centre[2] += (child & 1u) ? step : -step;
  }
  const auto& m = view.world_to_camera.m_q30;
  const double eye[3] = {static_cast<double>(view.camera.eye.x) / kFetchEdge,
                         static_cast<double>(view.camera.eye.y) / kFetchEdge,
                         static_cast<double>(view.camera.eye.z) / kFetchEdge};
  double z = 0;
  for (int a = 0; a < 3; ++a) z += m[2][a] / std::ldexp(1.0, 30) * (centre[a] - eye[a]);
  return {z, std::ldexp(1.0, -1 - region_level) * std::sqrt(3.0)};
}

class PerspectiveFetch : public ::testing::TestWithParam<bool> {};

TEST_P(PerspectiveFetch, NearestFirstWithinALevelCoarseBeforeFineNothingBehindOrTooFine) {
  const FetchFixture f;
  const ProgressiveModel model = f.tablesOnly();
  const bool far = GetParam();
  const PerspectiveView view = insideView(far);
  PerspectiveFetchOrder order;
  std::vector<FetchItem> items(100'000);
  std::size_t total = 0;
  items.resize(order.order(model, view, false, items, &total));
  ASSERT_EQ(items.size(), total);
  ASSERT_GT(items.size(), 10u);
  const double focal = static_cast<double>(view.focal_q16) / 65536;
  int previous_level = 0;
  double previous_near = -1e9;
  int levels_seen = 0;
  for (const FetchItem& item : items) {
    ASSERT_EQ(item.kind, FetchItem::Kind::kChunk);
    EXPECT_TRUE(item.visible);
    EXPECT_GE(item.level, previous_level) << "coarse levels first";
    if (item.level != previous_level) previous_near = -1e9, ++levels_seen;
    const RegionDepth depth = regionDepth(model, view, item);
    // A region that reaches the eye's depth is as near as can be: they all rank first.
    const double nearest = std::max(0.0, depth.z - depth.reach);
    EXPECT_GE(nearest, previous_near - 1e-6) << "nearest first within level " << item.level;
    previous_near = nearest;
    previous_level = item.level;
    EXPECT_GT(depth.z + depth.reach, 0) << "a region wholly behind the eye";
    // Detail by distance asks for this depth somewhere in the region: the next coarser depth's
    // voxel spans more than a pixel at its nearest point.
    const int coarser_depth = model.levelDepth(item.level - 1);
    EXPECT_TRUE(nearest == 0 || focal * std::ldexp(1.0, -coarser_depth) / nearest > 1 - 1e-6)
        << "level " << item.level << " fetched where depth " << coarser_depth << " suffices";
  }
  // From afar the finest depth is finer than a pixel all over: its level is not asked for.
  EXPECT_EQ(levels_seen, model.levelCount() - (far ? 2 : 1));
  // With the invisible ones: every visible one first, then the rest (from inside; from afar the
  // whole model is in view).
  std::vector<FetchItem> all(100'000);
  all.resize(order.order(model, view, true, all));
  if (far) {
    EXPECT_EQ(all.size(), items.size());
  } else {
    EXPECT_GT(all.size(), items.size());
  }
  for (std::size_t i = 0; i < all.size(); ++i) EXPECT_EQ(all[i].visible, i < items.size());
}

INSTANTIATE_TEST_SUITE_P(InsideAndFar, PerspectiveFetch, ::testing::Bool());

TEST(PerspectiveFetchPlan, TablesComeFirstAndHeldChunksAreNotAskedAgain) {
  const FetchFixture f;
  ChunkedIssue issue;
  const std::optional<ProgressiveModel> head = progressiveModelFromPrefix(
      std::span(f.image).first(static_cast<std::size_t>(*chunkedHeadBytes(f.image, &issue))),
      &issue);
  ASSERT_TRUE(head.has_value());
  PerspectiveFetchOrder order;
  std::vector<FetchItem> items(16);
  items.resize(order.order(*head, insideView(), true, items));
  ASSERT_EQ(items.size(), 1u);
  EXPECT_EQ(items[0], head->recordTableItem(1));

  // The planner asks for the order's first chunk (and its neighbours in the file); once they have
  // arrived they are not asked for again.
  ProgressiveModel model = f.tablesOnly();
  std::vector<FetchItem> first(1);
  ASSERT_EQ(order.order(model, insideView(), false, first), 1u);
  net::FetchPlanner planner(net::FetchPlanOptions{});
  net::FetchRange range;
  ASSERT_EQ(planner.next(model, insideView(), 1u << 30, range), net::FetchPlanner::Outcome::kRange);
  EXPECT_EQ(range.items.front(), first[0]);
  std::size_t delivered =
      planner.deliver(model, range, std::span(f.image).subspan(range.offset, range.size), 0,
                      [](const FetchItem&, const ChunkedIssue& taken) {
                        EXPECT_EQ(taken.error, ChunkedError::kNone);
                      });
  EXPECT_EQ(delivered, range.items.size());
  std::vector<FetchItem> after(100'000);
  after.resize(order.order(model, insideView(), true, after));
  for (const FetchItem& item : after) {
    for (const FetchItem& got : range.items) EXPECT_FALSE(item == got) << "asked again";
  }
}

void drawHeld(const HeldParts& parts, const PerspectiveView& view, Framebuffer& frame) {
  frame.clear();
  for (const std::unique_ptr<AssembledModel>& part : parts.parts)
    EXPECT_TRUE(PerspectiveRenderer(*part->view, parts.detailDepths()).draw(view, {}, frame));
}

// net::ModelStream following a perspective view: with no view it fetches the head alone; with a
// view it settles once that view is complete, having fetched no depth the view does not ask for
// (from afar, not the finest), and the parts it holds then draw the whole file's frame, bit for
// bit (renderer/chunked_assembly.h).
TEST(PerspectiveStream, FollowsTheViewAndDrawsTheWholeFilesFrame) {
  using namespace std::chrono_literals;
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
    const PerspectiveView view = insideView(far);
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
