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

#include "fixedpoint/trig.h"
#include "octopoint/framebuffer.h"
#include "octopoint/model.h"
#include "renderer/perspective.h"
#include "renderer/perspective_renderer.h"
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

// What a key held in walk mode moves along: forward follows the look's yaw, level; right is at
// right angles to it; up is the scan's up, -y of the model. In the order of WalkKey.
struct Direction {
  int forward, right, up;
};
constexpr std::array<Direction, web::kWalkKeys> kDirections = {
    {{1, 0, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}}};

std::int64_t joined(std::int32_t low, std::int32_t high) {
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(static_cast<std::uint32_t>(high))
                                       << 32 |
                                   static_cast<std::uint32_t>(low));
}

std::int64_t clampedEye(std::int64_t coordinate) {
  return std::clamp(coordinate, -kEyeLimit, kEyeLimit);
}

// `distance` (Q.24) times a Q1.30 sine or cosine, rounded.
std::int64_t along(std::int64_t distance, std::int32_t sine_q30) {
  return mulShiftRoundQuick(distance, sine_q30, 30).value_or(0);
}

// `eye` after `key` was held for `held_us` at `walker`'s speed and yaw: speed times time, exact to
// the unit below (whole seconds and the rest apart: no overflow), never past the camera's reach.
ModelPoint movedEye(const ModelPoint& eye, const Walker& walker, int key, std::int64_t held_us) {
  const Direction direction = kDirections[static_cast<std::size_t>(key)];
  const std::int64_t distance =
      std::min(held_us / 1'000'000 * walker.speed + held_us % 1'000'000 * walker.speed / 1'000'000,
               4 * kEyeLimit);
  const std::int64_t sine = along(distance, sinQ30(walker.yaw));
  const std::int64_t cosine = along(distance, cosQ30(walker.yaw));
  // Forward is (sin yaw, 0, cos yaw), right (cos yaw, 0, -sin yaw).
  const std::int64_t dx = direction.forward * sine + direction.right * cosine;
  const std::int64_t dz = direction.forward * cosine - direction.right * sine;
  const std::int64_t dy = -direction.up * distance;
  return {clampedEye(eye.x + dx), clampedEye(eye.y + dy), clampedEye(eye.z + dz)};
}

bool validKey(std::int32_t key) { return key >= 0 && key < web::kWalkKeys; }

// The walk's state as the page reads it (octopoint_web_walk_state).
using StateWords = std::array<std::uint32_t, 12>;

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

void publish(const Walker& shown) { stateWords() = wordsOf(shown); }

// The embedded model's perspective renderer: its indexes built once, at the first walk frame.
std::optional<PerspectiveRenderer>& perspectiveRenderer() {
  static std::optional<PerspectiveRenderer> instance;
  return instance;
}

}  // namespace

extern "C" {

const std::uint32_t* octopoint_web_walk_cube(void) {
  static std::array<std::uint32_t, 9> words{};
  const ModelView* model = web::embeddedModel();
  if (model == nullptr || !model->cubePlacement().recorded()) return nullptr;
  const CubePlacement& cube = model->cubePlacement();
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
  // The pitch stays within straight down .. straight up.
  constexpr std::int64_t kQuarter = Angle::kUnitsPerTurn / 4;
  std::int64_t pitch = walk.pitch.turns16();
  if (pitch > Angle::kUnitsPerTurn / 2) pitch -= Angle::kUnitsPerTurn;
  walk.pitch = Angle::fromTurns16(std::clamp(pitch + pitch_turns16, -kQuarter, kQuarter));
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
  const ModelView* model = web::embeddedModel();
  if (model == nullptr) return fail("walk mode draws the embedded model (not a chunked one yet)");
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
  camera.near = nearPlaneForDepth(model->finestLevel().depth);  // octopoint-render --eye's default
  camera.width = width;
  camera.height = height;
  PerspectiveView view;
  if (const PerspectiveError error = buildPerspectiveView(camera, kDefaultFractionBits, &view);
      error != PerspectiveError::kNone) {
    return fail(describe(error));
  }
  if (!perspectiveRenderer()) perspectiveRenderer().emplace(*model);
  web::Canvas& out = web::canvas();
  Framebuffer& frame = out.sized(width, height);
  frame.clear();
  PerspectiveRenderer::Options options;   // detail by distance, culled: octopoint-render --eye's
  options.coarser = coarse != 0 ? 1 : 0;  // while a key is held: octopoint-view's coarse frames
  if (!perspectiveRenderer()->draw(view, options, frame)) return fail("the walk's draw failed");
  if (!resolveToRgb(frame, *model, web::kBackground, out.rgb)) return fail("the resolve failed");
  out.toRgba();
  return succeed();
}

}  // extern "C"
