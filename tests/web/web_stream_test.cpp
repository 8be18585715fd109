// The web page's streaming interface (web/octopoint_web.h, "Streaming"), compiled natively and
// driven as web/octopoint_stream.js drives it: ask for the next request, serve its bytes from a
// real chunked file in pieces, end it; the frame of the complete view must be octopoint-render's
// frame of the same file (the progressive model read whole, drawn, resolved on its background), a
// damaged chunk must be refused and asked for again, a body longer than asked refused, and the
// order of the requests must follow the view last drawn.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "codegen/chunked_writer.h"
#include "octopoint/models.h"
#include "octopoint/progressive.h"
#include "renderer/chunked_assembly.h"
#include "renderer/perspective.h"
#include "renderer/perspective_renderer.h"
#include "tests/support/model_images.h"
#include "web/octopoint_web.h"
#include "web/web_canvas.h"

namespace octopoint {
namespace {

using Bytes = std::vector<std::uint8_t>;

// The default model at depths 5..8 in small chunks: many requests, several levels.
Bytes webStreamImage() {
  return prepare::serializeChunkedModel(
      fuzzing::preparedModel(*models::defaultModel(), {5, 6, 7, 8}), {64, 600});
}

struct WebView {
  std::int32_t yaw = 30000, pitch = 10000, roll = 0, zoom = 3 << 15, width = 320, height = 240;
  Camera camera() const {
    Camera c;
    c.yaw = Angle::fromMilliDegrees(yaw);
    c.pitch = Angle::fromMilliDegrees(pitch);
    c.roll = Angle::fromMilliDegrees(roll);
    c.zoom = Q16::fromRaw(zoom);
    c.width = width;
    c.height = height;
    return c;
  }
};

int drawWebView(const WebView& view) {
  return octopoint_web_draw(view.yaw, view.pitch, view.roll, view.zoom, view.width, view.height);
}

Bytes webPixels(const WebView& view) {
  const std::uint8_t* pixels = octopoint_web_pixels();
  return {pixels, pixels + std::size_t(view.width) * std::size_t(view.height) * 4};
}

// octopoint-render --file's frame of a chunked file (tools/chunked_render.cpp), as RGBA.
Bytes nativeChunkedFrame(std::span<const std::uint8_t> image, const WebView& view) {
  ChunkedIssue issue;
  std::optional<ProgressiveModel> model = progressiveModelFromPrefix(image, &issue);
  EXPECT_TRUE(model.has_value());
  const Camera camera = view.camera();
  Framebuffer frame(camera.width, camera.height);
  frame.clear();
  EXPECT_TRUE(model->draw(camera, defaultVariant(), frame));
  Bytes rgb(std::size_t(camera.width) * std::size_t(camera.height) * 3);
  EXPECT_TRUE(resolveToRgb(frame, model->baseModel(), web::kBackground, rgb));
  Bytes rgba;
  for (std::size_t i = 0; i < rgb.size(); i += 3)
    rgba.insert(rgba.end(), {rgb[i], rgb[i + 1], rgb[i + 2], 255});
  return rgba;
}

// What a served request saw.
struct Served {
  int requests = 0;
  int refusals = 0;     // receive() answered 1: a damaged part refused
  int damaged = 0;      // requests whose bytes were damaged on the way
  std::string refusal;  // the module's words for the last refusal
};

// Plays the page: asks for requests until there are none, serving each from `image` in pieces of
// `piece` bytes. `damage(offset, size)` returns the file offset of a byte to flip in this answer,
// or -1.
template <typename Damage>
Served serveAll(const Bytes& image, const WebView& view, std::size_t piece, Damage damage) {
  Served served;
  for (int round = 0; round < 10000; ++round) {
    drawWebView(view);  // as the page draws after each arrival: the view the order follows
    const std::int32_t id = octopoint_web_stream_next();
    if (id <= 0) break;
    const std::uint32_t* words = octopoint_web_stream_request();
    const std::uint64_t offset = words[0] | std::uint64_t{words[1]} << 32;
    const std::uint64_t size = std::min<std::uint64_t>(words[2], image.size() - offset);
    Bytes answer(image.begin() + std::ptrdiff_t(offset),
                 image.begin() + std::ptrdiff_t(offset + size));
    const std::int64_t flip = damage(offset, size);
    if (flip >= 0) {
      answer[std::size_t(flip - std::int64_t(offset))] ^= 0x5a;
      ++served.damaged;
    }
    ++served.requests;
    for (std::size_t at = 0; at < answer.size(); at += piece) {
      const std::size_t n = std::min(piece, answer.size() - at);
      std::memcpy(octopoint_web_input(std::int32_t(n)), answer.data() + at, n);
      const int taken = octopoint_web_stream_receive(id, std::int32_t(n));
      EXPECT_GE(taken, 0) << octopoint_web_error();
      if (taken == 1) {
        ++served.refusals;
        served.refusal = octopoint_web_error();
      }
    }
    EXPECT_EQ(octopoint_web_stream_end(id), 0) << octopoint_web_error();
  }
  return served;
}

class WebStream : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(octopoint_web_create(), 0);
    ASSERT_EQ(octopoint_web_stream_open(), 0);
  }
  void TearDown() override { octopoint_web_stream_close(); }
  Bytes image = webStreamImage();
};

TEST_F(WebStream, DrawsNothingBeforeTheHeadThenTheCompleteViewAsOctopointRenderDoes) {
  const WebView view;
  EXPECT_EQ(drawWebView(view), -1);  // the head has not arrived
  const Served served =
      serveAll(image, view, 1000, [](std::uint64_t, std::uint64_t) { return -1; });
  EXPECT_GT(served.requests, 2);
  const std::uint32_t* status = octopoint_web_stream_status();
  EXPECT_EQ(status[0], 2u);  // drawing
  EXPECT_EQ(status[6], 0u);  // nothing of the view pending
  EXPECT_EQ(status[7], 1u);  // the view complete
  ASSERT_EQ(drawWebView(view), 0) << octopoint_web_error();
  EXPECT_EQ(webPixels(view), nativeChunkedFrame(image, view));
  // The point budget bounds what a frame draws, and the status says how many it drew.
  const std::uint32_t all = octopoint_web_stream_status()[10];
  ASSERT_EQ(octopoint_web_set_point_budget(std::int32_t(all / 4)), 0);
  ASSERT_EQ(drawWebView(view), 0) << octopoint_web_error();
  const std::uint32_t budgeted = octopoint_web_stream_status()[10];
  EXPECT_LT(budgeted, all);
  EXPECT_GT(budgeted, 0u);
  EXPECT_NE(webPixels(view), nativeChunkedFrame(image, view));
}

TEST_F(WebStream, RefusesADamagedChunkAndAsksForItAgain) {
  const WebView view;
  // Damage the first byte of the first request for chunks (after the head and the record tables,
  // wherever the format puts them): the first byte of a chunk, whose CRC then fails.
  ChunkedIssue issue;
  const std::optional<ChunkedHead> head = parseChunkedHead(image, &issue);
  ASSERT_TRUE(head.has_value()) << describe(issue.error);
  ASSERT_GE(head->level_count, 2);
  const std::uint64_t first_chunk = head->levels[1].chunks_offset;
  std::uint64_t damaged_at = 0;
  int asked_again = 0;
  const Served served = serveAll(image, view, 700, [&](std::uint64_t offset, std::uint64_t) {
    if (damaged_at != 0 && offset == damaged_at) ++asked_again;
    if (damaged_at != 0 || offset < first_chunk) return std::int64_t{-1};
    damaged_at = offset;
    return std::int64_t(offset);
  });
  EXPECT_GE(damaged_at, first_chunk);
  EXPECT_EQ(asked_again, 1);
  EXPECT_EQ(served.damaged, 1);
  EXPECT_EQ(served.refusals, 1);
  EXPECT_EQ(octopoint_web_stream_status()[8], 1u);  // one part refused
  EXPECT_NE(served.refusal.find("refused a damaged chunk"), std::string::npos) << served.refusal;
  ASSERT_EQ(drawWebView(view), 0) << octopoint_web_error();
  EXPECT_EQ(webPixels(view), nativeChunkedFrame(image, view));
}

TEST_F(WebStream, RefusesABodyLongerThanAskedAndAsksAgain) {
  const WebView view;
  drawWebView(view);
  const std::int32_t head = octopoint_web_stream_next();
  ASSERT_GT(head, 0);
  const std::uint32_t asked = octopoint_web_stream_request()[2];
  std::memcpy(octopoint_web_input(std::int32_t(asked)), image.data(), asked);
  ASSERT_EQ(octopoint_web_stream_receive(head, std::int32_t(asked)), 0);
  const std::int32_t id = octopoint_web_stream_next();
  ASSERT_GT(id, 0);
  const std::uint32_t* words = octopoint_web_stream_request();
  const std::uint64_t offset = words[0];
  const std::uint32_t size = words[2];
  std::memcpy(octopoint_web_input(std::int32_t(size + 1)), image.data() + offset, size + 1);
  EXPECT_EQ(octopoint_web_stream_receive(id, std::int32_t(size + 1)), -1);
  EXPECT_NE(std::string(octopoint_web_error()).find("more bytes than"), std::string::npos);
  // The request is over; its parts are asked for again.
  EXPECT_EQ(octopoint_web_stream_end(id), -1);
  EXPECT_EQ(octopoint_web_stream_end(head), 0);
  const std::int32_t again = octopoint_web_stream_next();
  ASSERT_GT(again, 0);
  EXPECT_EQ(octopoint_web_stream_request()[0], offset);
}

TEST_F(WebStream, StopsForGoodOnAHeadThatIsNotAChunkedModel) {
  const WebView view;
  drawWebView(view);
  const std::int32_t id = octopoint_web_stream_next();
  ASSERT_GT(id, 0);
  Bytes wrong(image.begin(), image.begin() + 4096);
  wrong[0] = 'X';  // not the magic
  std::memcpy(octopoint_web_input(4096), wrong.data(), 4096);
  EXPECT_EQ(octopoint_web_stream_receive(id, 4096), -1);
  EXPECT_NE(std::string(octopoint_web_error()).find("not a chunked model"), std::string::npos);
  octopoint_web_stream_end(id);
  EXPECT_EQ(octopoint_web_stream_next(), -1);
  EXPECT_EQ(octopoint_web_stream_status()[0], 3u);  // failed
  EXPECT_EQ(drawWebView(view), -1);
}

// Plays the page for `view` until the view is complete: the offsets of the requests it made.
// The offsets of the requests until `draw()` (0: drawn) draws a complete view, serving each whole.
template <typename Draw>
std::vector<std::uint64_t> offsetsUntilDrawnComplete(const Bytes& image, Draw draw) {
  std::vector<std::uint64_t> offsets;
  for (int round = 0; round < 10000; ++round) {
    const bool drew = draw() == 0;  // the view the order follows
    if (drew && octopoint_web_stream_status()[7] == 1) break;
    const std::int32_t id = octopoint_web_stream_next();
    if (id <= 0) break;
    const std::uint32_t* words = octopoint_web_stream_request();
    const std::uint64_t offset = words[0] | std::uint64_t{words[1]} << 32;
    const std::uint64_t size = std::min<std::uint64_t>(words[2], image.size() - offset);
    offsets.push_back(offset);
    std::memcpy(octopoint_web_input(std::int32_t(size)), image.data() + offset, size);
    EXPECT_EQ(octopoint_web_stream_receive(id, std::int32_t(size)), 0) << octopoint_web_error();
    EXPECT_EQ(octopoint_web_stream_end(id), 0) << octopoint_web_error();
  }
  return offsets;
}

std::vector<std::uint64_t> offsetsUntilViewComplete(const Bytes& image, const WebView& view) {
  return offsetsUntilDrawnComplete(image, [&view] { return drawWebView(view); });
}

TEST_F(WebStream, AsksForWhatTheLastDrawnViewSeesFirst) {
  // Close up (zoom 4: a column through the middle of the model) from the front and from above:
  // each view asks for its own parts first, and is complete before the whole file has come.
  WebView front;
  front.zoom = 4 << 16;
  WebView above = front;
  above.pitch = 90000;
  const std::vector<std::uint64_t> for_front = offsetsUntilViewComplete(image, front);
  ASSERT_EQ(octopoint_web_stream_open(), 0);  // a new stream of the same file
  const std::vector<std::uint64_t> for_above = offsetsUntilViewComplete(image, above);
  EXPECT_NE(for_front, for_above);
  ASSERT_EQ(drawWebView(above), 0) << octopoint_web_error();
  EXPECT_EQ(webPixels(above), nativeChunkedFrame(image, above));
  // The rest of the file: more requests still.
  const Served rest = serveAll(image, above, 1000, [](std::uint64_t, std::uint64_t) { return -1; });
  EXPECT_GT(rest.requests, 0);
  ASSERT_EQ(octopoint_web_stream_open(), 0);
  const Served all = serveAll(image, front, 1000, [](std::uint64_t, std::uint64_t) { return -1; });
  EXPECT_LT(for_front.size(), std::size_t(all.requests));
}

// Walk mode on the streamed model: the eye placed (Q.24 about the cube's centre) once the head is
// in, its frame drawn (320x240, fov 60); 0 when drawn.
int drawWalkAt(const ModelPoint& eye, std::int32_t yaw_millidegrees) {
  if (octopoint_web_walk_cube() == nullptr) return -1;  // the head is not in yet
  const auto low = [](std::int64_t v) { return std::int32_t(std::uint32_t(std::uint64_t(v))); };
  const auto high = [](std::int64_t v) { return std::int32_t(std::uint64_t(v) >> 32); };
  EXPECT_EQ(octopoint_web_walk_place(low(eye.x), high(eye.x), low(eye.y), high(eye.y), low(eye.z),
                                     high(eye.z), yaw_millidegrees, -10000, 0, 60000),
            0);
  return octopoint_web_walk_draw(320, 240, 0, 0, 0, 0, 0, 0, 0);
}

// octopoint-render --url --eye's frame of the same eye from the whole file: its held parts each
// drawn by the perspective renderer (tools/perspective_render.cpp, renderPerspectiveParts),
// resolved on its background, as RGBA; `points` gets the points the parts that drew drew.
Bytes nativePartsFrame(std::span<const std::uint8_t> image, const ModelPoint& eye,
                       std::int32_t yaw_millidegrees, std::uint64_t* points) {
  ChunkedIssue issue;
  std::optional<ProgressiveModel> model = progressiveModelFromPrefix(image, &issue);
  EXPECT_TRUE(model.has_value());
  PerspectiveCamera camera;
  camera.eye = eye;
  camera.yaw = Angle::fromMilliDegrees(yaw_millidegrees);
  camera.pitch = Angle::fromMilliDegrees(-10000);
  camera.near = nearPlaneForDepth(model->baseModel().finestLevel().depth);
  PerspectiveView view;
  EXPECT_EQ(buildPerspectiveView(camera, kDefaultFractionBits, &view), PerspectiveError::kNone);
  const HeldParts parts = assembleHeldParts(*model);
  Framebuffer frame(camera.width, camera.height);
  frame.clear();
  *points = 0;
  for (const std::unique_ptr<AssembledModel>& part : parts.parts) {
    PerspectiveDrawStats drawn;
    if (PerspectiveRenderer(*part->view, parts.detailDepths()).draw(view, {}, frame, &drawn))
      *points += drawn.leaves;
  }
  Bytes rgb(std::size_t(camera.width) * std::size_t(camera.height) * 3);
  EXPECT_TRUE(resolveToRgb(frame, *parts.parts.front()->view, web::kBackground, rgb));
  Bytes rgba;
  for (std::size_t i = 0; i < rgb.size(); i += 3)
    rgba.insert(rgba.end(), {rgb[i], rgb[i + 1], rgb[i + 2], 255});
  return rgba;
}

TEST_F(WebStream, WalksTheStreamedModelFetchingWhatTheEyeSeesFirst) {
  // The file as octopoint-prepare writes it from a scan: with its cube's place in the scan.
  prepare::PreparedModel prepared = fuzzing::preparedModel(*models::defaultModel(), {5, 6, 7, 8});
  prepared.cube = web::embeddedModel()->cubePlacement();
  image = prepare::serializeChunkedModel(prepared, {64, 600});
  // Nothing to walk in before the head.
  EXPECT_EQ(octopoint_web_walk_cube(), nullptr);
  EXPECT_NE(octopoint_web_walk_draw(320, 240, 0, 0, 0, 0, 0, 0, 0), 0);
  // Two eyes inside the cube's edge, looking in opposite directions: each asks for its own parts
  // first (the perspective fetch order).
  const ModelPoint front{0, -kPerspectiveUnit / 8, -kPerspectiveUnit * 3 / 4};
  const ModelPoint back{0, -kPerspectiveUnit / 8, kPerspectiveUnit * 3 / 4};
  const std::vector<std::uint64_t> for_front =
      offsetsUntilDrawnComplete(image, [&] { return drawWalkAt(front, 0); });
  ASSERT_EQ(octopoint_web_stream_open(), 0);  // a new stream of the same file
  const std::vector<std::uint64_t> for_back =
      offsetsUntilDrawnComplete(image, [&] { return drawWalkAt(back, 180000); });
  EXPECT_NE(for_front, for_back);
  // The complete view's frame is octopoint-render --url --eye's, pixel for pixel.
  ASSERT_EQ(drawWalkAt(back, 180000), 0) << octopoint_web_error();
  const WebView size;
  std::uint64_t points = 0;
  EXPECT_EQ(webPixels(size), nativePartsFrame(image, back, 180000, &points));
  // The overlay's points drawn (the walk state's last word): octopoint-render --url --eye's.
  ASSERT_GT(points, 0u);
  EXPECT_EQ(octopoint_web_walk_state()[12], points);
  // And the rest of the file changes nothing of it.
  const Served rest = serveAll(image, size, 1000, [](std::uint64_t, std::uint64_t) { return -1; });
  EXPECT_GT(rest.requests, 0);
  ASSERT_EQ(drawWalkAt(back, 180000), 0) << octopoint_web_error();
  EXPECT_EQ(webPixels(size), nativePartsFrame(image, back, 180000, &points));
  EXPECT_EQ(octopoint_web_walk_state()[12], points);
}

}  // namespace
}  // namespace octopoint
