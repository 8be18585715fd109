// The smooth RAM budget image (docs/device.md, "Smooth splats in bands"): smooth splats on a
// 320x240 panel as a device would hold them, the default model at depth 8 zoomed in, bands of
// kSmoothBandRows rows, one band buffer, fixed_fast's box pass with the deepest subtree index that
// fits, and the blend's sums and weights in this image's own memory (SmoothSplats::Memory: no
// heap). Linked with -Wl,--defsym=__ram_budget=N, so the image does not link if its RAM (.data,
// .bss and the stack reserved for it) exceeds the target; run, it draws both smooth cameras of
// band_cases.h, checks every band against the host's whole smooth frame and reports the stack's
// high-water mark, each part of its RAM and the instructions a frame.
#include <array>
#include <cstdint>
#include <memory>

#include "mcu/golden.h"
#include "octopoint/smooth.h"
#include "targets/cortex-m/band_check.h"
#include "targets/cortex-m/semihosting.h"

using namespace octopoint;
using namespace octopoint::mcu;

namespace {

constexpr std::int32_t kWidth = 320;
constexpr std::int32_t kRows = kSmoothBandRows;
constexpr std::size_t kIndexCapacity = 120;
constexpr std::size_t kBandPixels = static_cast<std::size_t>(kRows) * kWidth;

// The renderer's state, all of it here (and the stack): what the RAM budget covers.
alignas(8) std::uint32_t band_buffer[kBandPixels];
SmoothSplats::Sums sums[kBandPixels];
std::uint16_t column_weights[kWidth];
std::uint16_t row_weights[kRows];
// Made at boot in place and never destroyed: no heap, no exit-time destructor.
alignas(SmoothSplats) unsigned char smooth_storage[sizeof(SmoothSplats)];
std::array<SubtreeSize, kIndexCapacity> index_storage;
BandIndex band_index;
Rgb565Palette palette;
PaletteRgb colours;
FrameSetup setup;

}  // namespace

int octopoint::mcu::programMain() {
  startInstructionClock();
  const ModelView& model = defaultModel();
  const LevelView& level = *model.levelOfDepth(kSmoothDepth);
  palette = makeRgb565Palette(model, kBackground);
  colours = paletteOf(model);
  band_index = buildBandIndex(level, deepestIndexLevel(level, kIndexCapacity), index_storage);
  SmoothSplats& smooth =
      *std::construct_at(static_cast<SmoothSplats*>(static_cast<void*>(smooth_storage)), kWidth,
                         kRows, SmoothSplats::Memory{sums, column_weights, row_weights});
  const std::uint32_t setup_stack = stackHighWater();
  paintStack();  // from here on, the high-water mark is the frames' alone
  int failures = 0;
  for (int i = 0; i < kSmoothCaseCount; ++i) {
    const Camera& camera = kSmoothCameras[i];
    if (buildFrameSetup(camera, kSmoothDepth, kDefaultFractionBits, &setup) != CameraError::kNone)
      return 1;
    GoldenSink golden(kGoldenSmoothBands + kGoldenSmoothFirst[i], kRows, kWidth, camera.height);
    const BandConfig config{Variant::kFixedFast, kRows, false, kBackground};
    const std::uint64_t start = instructionsNow();
    const BandError error = renderSmoothBands(level, setup, config, band_index, palette, colours,
                                              {band_buffer, {}, {}}, smooth, golden.sink());
    const std::uint64_t spent = instructionsNow() - start - golden.flushInstructions();
    if (error != BandError::kNone) {
      print("renderSmoothBands: ");
      print(describe(error));
      print("\n");
    }
    const bool passed = error == BandError::kNone && golden.passed();
    failures += passed ? 0 : 1;
    print(passed ? "pass" : "FAIL");
    print(" smooth camera ");
    printUnsigned(static_cast<std::uint64_t>(i));
    report(" instructions", spent);
  }
  report("band rows", kRows);
  report("index level", static_cast<std::uint64_t>(band_index.level));
  report("ram band buffer bytes", sizeof band_buffer);
  report("ram smooth sums bytes", sizeof sums);
  report("ram smooth weights bytes", sizeof column_weights + sizeof row_weights);
  report("ram smooth object bytes", sizeof smooth_storage);
  report("ram index storage bytes", sizeof index_storage);
  report("ram palettes bytes (rgb565, rgb)", sizeof palette + sizeof colours);
  report("ram frame setup bytes", sizeof setup);
  report("ram model view bytes", sizeof(ModelView));
  return finishBudgetReport(setup_stack, failures);
}
