// The page's walk mode (docs/web.md, "Walk mode"): the eye standing in the embedded model, moved by
// held keys and turned by drags as octopoint-view's walk mode moves it (docs/perspective.md, "The
// viewer's walk mode"), and its frame drawn as octopoint-render --eye --look --fov draws it
// (tools/perspective_render.cpp: detail by distance, culled, colour). Integer only: the page
// converts between the scan's units and the camera's Q.24 cube edges (web/octopoint_walk.js, with
// the doubles of tools/scan_eye.cpp); the module keeps the eye, moves it and draws.
#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>

#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "renderer/perspective.h"
#include "renderer/perspective_renderer.h"
#include "renderer/walk_motion.h"
#include "web/held_parts_frame.h"
#include "web/octopoint_web.h"
#include "web/web_canvas.h"

namespace {

using namespace octopoint;
using web::fail;
using web::succeed;

// The walk speed, Q.24 cube edges a second: octopoint-view's default (a quarter cube edge a
// second), its bounds (1/1024 to 64) and its wheel step (5/4).
constexpr std::int64_t kDefaultSpeed = std::int64_t{1} << 22;
constexpr std::int64_t kMinSpeed = std::int64_t{1} << 14;
constexpr std::int64_t kMaxSpeed = std::int64_t{1} << 30;
constexpr std::int64_t kEyeLimit = kMaxEyeDistance * kPerspectiveUnit;  // Q.24, each axis

struct Walker {
  ModelPoint eye{0, 0, -2 * kPerspectiveUnit};
  Angle yaw, pitch, roll, fov = Angle::fromDegrees(60);
  std::int64_t speed = kDefaultSpeed;
};

Walker& walker() {  // the eye with every key hold folded in so far
  static Walker instance;
  return instance;
}

// The page's keys are the walk's steps, in their order (0 forward ... 5 down).
static_assert(web::kWalkKeys == kWalkSteps);

std::int64_t joined(std::int32_t low, std::int32_t high) {
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(static_cast<std::uint32_t>(high))
                                       << 32 |
                                   static_cast<std::uint32_t>(low));
}

// `eye` after `key` was held for `held_us` at `walker`'s speed and yaw (renderer/walk_motion.h:
// octopoint-view's walk, without collision).
ModelPoint movedEye(const ModelPoint& eye, const Walker& walker, int key, std::int64_t held_us) {
  return walkedEye(eye, walker.yaw, static_cast<WalkStep>(key),
                   walkDistance(held_us, walker.speed));
}

bool validKey(std::int32_t key) { return key >= 0 && key < web::kWalkKeys; }

// The walk's state as the page reads it (octopoint_web_walk_state).
using StateWords = std::array<std::uint32_t, 13>;

StateWords wordsOf(const Walker& shown) {
  StateWords words{};
  const std::int64_t coordinates[3] = {shown.eye.x, shown.eye.y, shown.eye.z};
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const auto bits = static_cast<std::uint64_t>(coordinates[axis]);
    words[axis * 2] = static_cast<std::uint32_t>(bits);
    words[axis * 2 + 1] = static_cast<std::uint32_t>(bits >> 32);
  }
  words[6] = static_cast<std::uint32_t>(shown.yaw.turns16());
  words[7] = static_cast<std::uint32_t>(shown.pitch.turns16());
  words[8] = static_cast<std::uint32_t>(shown.roll.turns16());
  words[9] = static_cast<std::uint32_t>(shown.fov.turns16());
  words[10] = static_cast<std::uint32_t>(shown.speed);
  words[11] = static_cast<std::uint32_t>(shown.speed >> 32);
  return words;
}

StateWords& stateWords() {  // the walker's from the start: the speed is right before any call
  static StateWords words = wordsOf(walker());
  return words;
}

// The eye's words; the last draw's points stay until the next draw says its own.
void publish(const Walker& shown) {
  const std::uint32_t points = stateWords()[12];
  stateWords() = wordsOf(shown);
  stateWords()[12] = points;
}

// The points (leaves handed to the plot) the last walk frame drew, as octopoint-render --eye
// prints them ("N points drawn"), at most 2^32 - 1.
void publishPoints(const PerspectiveDrawStats& stats) {
  stateWords()[12] = static_cast<std::uint32_t>(std::min<std::uint64_t>(stats.leaves, UINT32_MAX));
}

#if OCTOPOINT_WEB_EMBEDDED_MODEL
// The embedded model's perspective renderer: its indexes built once, at the first walk frame.
std::optional<PerspectiveRenderer>& perspectiveRenderer() {
  static std::optional<PerspectiveRenderer> instance;
  return instance;
}
#endif

// The chunked model's: its held parts, assembled again as chunks arrive.
web::HeldPartsFrame& heldPartsFrame() {
  static web::HeldPartsFrame instance;
  return instance;
}

// The model walked in: the chunked model the page opened (its base, for the palette and the near
// plane, once its head is in), else the embedded one; null when neither.
const ModelView* walkedModel() {
  if (!web::streamOpen()) return web::embeddedModel();
  const ProgressiveModel* chunked = web::streamModel();
  return chunked != nullptr ? &chunked->baseModel() : nullptr;
}

// Where its cube lies in the scan (a chunked model's head records it from format version 5 on);
// null when nowhere.
const CubePlacement* walkedCube() {
  const CubePlacement* cube = nullptr;
  if (!web::streamOpen()) {
    if (const ModelView* model = web::embeddedModel()) cube = &model->cubePlacement();
  } else if (const ProgressiveModel* chunked = web::streamModel()) {
    if (chunked->head().format_version != chunked::kVersion3) cube = &chunked->head().cube;
  }
  return cube != nullptr && cube->recorded() ? cube : nullptr;
}

}  // namespace

extern "C" {

const std::uint32_t* octopoint_web_walk_cube(void) {
  static std::array<std::uint32_t, 9> words{};
  const CubePlacement* placed = walkedCube();
  if (placed == nullptr) return nullptr;
  const CubePlacement& cube = *placed;
  const std::uint64_t bits[4] = {cube.corner_bits[0], cube.corner_bits[1], cube.corner_bits[2],
                                 cube.edge_bits};
  for (std::size_t i = 0; i < 4; ++i) {
    words[i * 2] = static_cast<std::uint32_t>(bits[i]);
    words[i * 2 + 1] = static_cast<std::uint32_t>(bits[i] >> 32);
  }
  words[8] = cube.scan_axes == format::kScanAxesYUp ? 1 : 0;
  return words.data();
}

int octopoint_web_walk_place(std::int32_t x_low, std::int32_t x_high, std::int32_t y_low,
                             std::int32_t y_high, std::int32_t z_low, std::int32_t z_high,
                             std::int32_t yaw_millidegrees, std::int32_t pitch_millidegrees,
                             std::int32_t roll_millidegrees, std::int32_t fov_millidegrees) {
  const ModelPoint eye{joined(x_low, x_high), joined(y_low, y_high), joined(z_low, z_high)};
  if (std::max({eye.x, eye.y, eye.z}) > kEyeLimit || std::min({eye.x, eye.y, eye.z}) < -kEyeLimit)
    return fail("the eye is more than 128 cube edges from the model's centre");
  if (fov_millidegrees < kMinFieldOfViewDegrees * 1000 ||
      fov_millidegrees > kMaxFieldOfViewDegrees * 1000) {
    return fail(describe(PerspectiveError::kBadFieldOfView));
  }
  Walker& walk = walker();
  walk.eye = eye;
  walk.yaw = Angle::fromMilliDegrees(yaw_millidegrees);
  walk.pitch = Angle::fromMilliDegrees(pitch_millidegrees);
  walk.roll = Angle::fromMilliDegrees(roll_millidegrees);
  walk.fov = Angle::fromMilliDegrees(fov_millidegrees);
  publish(walk);
  return succeed();
}

int octopoint_web_walk_enter(std::int32_t yaw_millidegrees, std::int32_t pitch_millidegrees,
                             std::int32_t roll_millidegrees, std::int32_t zoom_q16,
                             std::int32_t width, std::int32_t height) {
  Camera camera;
  camera.yaw = Angle::fromMilliDegrees(yaw_millidegrees);
  camera.pitch = Angle::fromMilliDegrees(pitch_millidegrees);
  camera.roll = Angle::fromMilliDegrees(roll_millidegrees);
  camera.zoom = Q16::fromRaw(zoom_q16);
  camera.width = width;
  camera.height = height;
  Walker& walk = walker();
  PerspectiveView view;
  if (const PerspectiveError error =
          orbitPerspective(camera, walk.fov, kDefaultFractionBits, &view);
      error != PerspectiveError::kNone) {
    publish(walk);  // the last walk eye stays (octopoint-view does the same)
    return fail(describe(error));
  }
  walk.eye = view.camera.eye;
  walk.yaw = view.camera.yaw;
  walk.pitch = view.camera.pitch;
  walk.roll = view.camera.roll;
  publish(walk);
  return succeed();
}

int octopoint_web_walk_move(std::int32_t key, std::int32_t held_us) {
  if (!validKey(key) || held_us < 0) return fail("no such walk key, or a negative time");
  Walker& walk = walker();
  walk.eye = movedEye(walk.eye, walk, key, held_us);
  publish(walk);
  return succeed();
}

int octopoint_web_walk_turn(std::int32_t yaw_turns16, std::int32_t pitch_turns16) {
  Walker& walk = walker();
  walk.yaw = walk.yaw + Angle::fromTurns16(yaw_turns16);
  walk.pitch = turnedPitch(walk.pitch, pitch_turns16);
  publish(walk);
  return succeed();
}

int octopoint_web_walk_faster(std::int32_t faster) {
  Walker& walk = walker();
  walk.speed =
      std::clamp(faster != 0 ? walk.speed * 5 / 4 : walk.speed * 4 / 5, kMinSpeed, kMaxSpeed);
  publish(walk);
  return succeed();
}

const std::uint32_t* octopoint_web_walk_state(void) { return stateWords().data(); }

int octopoint_web_walk_draw(std::int32_t width, std::int32_t height, std::int32_t coarse,
                            std::int32_t forward_us, std::int32_t back_us, std::int32_t left_us,
                            std::int32_t right_us, std::int32_t up_us, std::int32_t down_us) {
  const ModelView* model = walkedModel();
  if (model == nullptr) {
    return fail(web::streamOpen() ? "waiting for the chunked model's head"
                                  : "no model to walk in: open a chunked one (model=NAME.oct)");
  }
  if (!web::sizeAllowed(width, height)) return fail(web::kSizeRule);
  // The eye of this frame: each key held moved it by its time so far (folded in when let go).
  const std::int32_t held[web::kWalkKeys] = {forward_us, back_us, left_us,
                                             right_us,   up_us,   down_us};
  Walker shown = walker();
  for (int key = 0; key < web::kWalkKeys; ++key)
    if (held[key] > 0) shown.eye = movedEye(shown.eye, shown, key, held[key]);
  publish(shown);
  PerspectiveCamera camera;
  camera.eye = shown.eye;
  camera.yaw = shown.yaw;
  camera.pitch = shown.pitch;
  camera.roll = shown.roll;
  camera.fov = shown.fov;
  // octopoint-render --eye's default near plane: the model's finest depth (a chunked model's
  // head's, as --url takes it: its base's).
  camera.near = nearPlaneForDepth(model->finestLevel().depth);
  camera.width = width;
  camera.height = height;
  PerspectiveView view;
  if (const PerspectiveError error = buildPerspectiveView(camera, kDefaultFractionBits, &view);
      error != PerspectiveError::kNone) {
    return fail(describe(error));
  }
  web::Canvas& out = web::canvas();
  Framebuffer& frame = out.sized(width, height);
  frame.clear();
  PerspectiveDrawStats stats;  // the renderer adds to it: this frame's
  if (web::streamOpen()) {
    web::streamFollow(view);  // the fetch order follows the eye from now on
    if (!heldPartsFrame().draw(*web::streamModel(), web::streamTaken(), view, coarse != 0, frame,
                               &stats)) {
      return fail("nothing of the chunked model is held yet");
    }
  }
#if OCTOPOINT_WEB_EMBEDDED_MODEL  // (the page without a model walks only in what it streams)
  else {
    if (!perspectiveRenderer()) perspectiveRenderer().emplace(*model);
    PerspectiveRenderer::Options options;   // detail by distance, culled: octopoint-render --eye's
    options.coarser = coarse != 0 ? 1 : 0;  // while a key is held: octopoint-view's coarse frames
    if (!perspectiveRenderer()->draw(view, options, frame, &stats))
      return fail("the walk's draw failed");
  }
#endif
  out.resolveColour(*model, web::kBackground);
  publishPoints(stats);
  return succeed();
}

}  // extern "C"
