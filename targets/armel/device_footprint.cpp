// device_footprint: what the integer core needs on the device (docs/device.md). ROM: the embedded
// model's bytes (code size comes from `size`, see the doc). RAM: framebuffer (one palette index
// per pixel) and z-buffer (int32 per pixel) for the paper's phone screens, and the stack of one
// frame's decode, measured per variant by painting a thread's stack and finding the deepest byte
// the frame overwrote.
#include <pthread.h>

#include <algorithm>
#include <array>
#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <vector>

#include "octopoint/models.h"
#include "octopoint/render.h"

namespace octopoint {
namespace {

struct Screen {
  std::int32_t width, height;
};
constexpr std::array kScreens = {Screen{176, 208}, Screen{240, 320}, Screen{320, 240}};
constexpr std::size_t kPaintedStackBytes = 256 * 1024;
constexpr std::uint8_t kPaint = 0xA5;

struct StackProbe {
  Variant variant;
  const LevelView* level;
  const FrameSetup* setup;
  Framebuffer* frame;
  std::uintptr_t stack_pointer_at_call = 0;
  bool complete = false;
};

void* renderOnPaintedStack(void* argument) {
  auto* probe = static_cast<StackProbe*>(argument);
  // The address of a local is where this thread's stack stands when the decode is called.
  probe->stack_pointer_at_call = reinterpret_cast<std::uintptr_t>(&probe);
  asm volatile("" : : "r"(&probe) : "memory");  // keep `probe` in this frame, in memory
  probe->complete = renderLevel(probe->variant, *probe->level, *probe->setup, *probe->frame);
  return nullptr;
}

// Bytes of stack one frame of `variant` uses below its caller (the stack grows down on ARM and
// x86), or nullopt when the thread could not run.
std::optional<std::size_t> measureStack(StackProbe probe) {
  std::vector<std::uint8_t> stack(kPaintedStackBytes, kPaint);
  pthread_attr_t attributes;
  pthread_attr_init(&attributes);
  pthread_attr_setstack(&attributes, stack.data(), stack.size());
  pthread_t thread;
  const bool started = pthread_create(&thread, &attributes, renderOnPaintedStack, &probe) == 0;
  pthread_attr_destroy(&attributes);
  if (!started || pthread_join(thread, nullptr) != 0 || !probe.complete) return std::nullopt;
  const auto untouched =
      std::find_if(stack.begin(), stack.end(), [](std::uint8_t b) { return b != kPaint; });
  const std::uintptr_t deepest = reinterpret_cast<std::uintptr_t>(stack.data()) +
                                 static_cast<std::uintptr_t>(untouched - stack.begin());
  return probe.stack_pointer_at_call - deepest;
}

int run() {
  ModelIssue issue;
  const EmbeddedModel& embedded = *models::defaultModel();
  const std::optional<ModelView> model = ModelView::fromEmbedded(embedded, &issue);
  if (!model) {
    std::fprintf(stderr, "device_footprint: the embedded model '%s' is invalid: %s\n",
                 embedded.name, describe(issue.error));
    return 1;
  }

  std::printf("ROM: model '%s' (palette %d colours = 768 bytes of RGB888)\n\n", embedded.name,
              model->paletteCount());
  std::printf(
      "| depth | node bytes | leaf bytes | level total | with palette |\n|---|---|---|---|---|\n");
  std::size_t all_levels = 0;
  for (int i = 0; i < model->levelCount(); ++i) {
    const LevelView& level = model->level(i);
    const std::size_t bytes = level.nodes.size() + level.leaves.size();
    all_levels += bytes;
    std::printf("| %d | %zu | %zu | %zu | %zu |\n", level.depth, level.nodes.size(),
                level.leaves.size(), bytes, bytes + 768);
  }
  std::printf("| all | | | %zu | %zu |\n\n", all_levels, all_levels + 768);

  std::printf("RAM: frame buffers (palette index + int32 z-buffer per pixel)\n\n");
  std::printf("| screen | framebuffer | z-buffer | total |\n|---|---|---|---|\n");
  for (const Screen& screen : kScreens) {
    const std::size_t pixels =
        static_cast<std::size_t>(screen.width) * static_cast<std::size_t>(screen.height);
    std::printf("| %dx%d | %zu | %zu | %zu |\n", screen.width, screen.height, pixels,
                pixels * sizeof(std::int32_t), pixels * (1 + sizeof(std::int32_t)));
  }

  std::printf("\nRAM: stack of one frame's decode, measured (painted %zu KiB thread stack)\n\n",
              kPaintedStackBytes / 1024);
  std::printf("| variant |");
  for (int i = 0; i < model->levelCount(); ++i) std::printf(" depth %d |", model->level(i).depth);
  std::printf("\n|---|");
  for (int i = 0; i < model->levelCount(); ++i) std::printf("---|");
  std::printf("\n");
  Framebuffer frame(320, 240);
  Camera camera;
  camera.yaw = Angle::fromDegrees(30);
  for (const VariantInfo& info : allVariants()) {
    std::printf("| %.*s |", static_cast<int>(info.name.size()), info.name.data());
    for (int i = 0; i < model->levelCount(); ++i) {
      const LevelView& level = model->level(i);
      FrameSetup setup;
      if (buildFrameSetup(camera, level.depth, kDefaultFractionBits, &setup) !=
          CameraError::kNone) {
        std::fprintf(stderr, "device_footprint: camera refused at depth %d\n", level.depth);
        return 1;
      }
      frame.clear();
      const std::optional<std::size_t> bytes = measureStack({info.variant, &level, &setup, &frame});
      if (!bytes) {
        std::fprintf(stderr, "device_footprint: could not run %.*s on a painted stack\n",
                     static_cast<int>(info.name.size()), info.name.data());
        return 1;
      }
      std::printf(" %zu |", *bytes);
    }
    std::printf("\n");
  }
  return 0;
}

}  // namespace
}  // namespace octopoint

int main() { return octopoint::run(); }
