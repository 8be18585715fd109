// The RAM budget images (docs/device.md): the renderer as a device would hold it for a 320x240
// panel, the default model at depth 8, bands of OCTOPOINT_BAND_ROWS rows (24 or 8), one band
// buffer, fixed_delta (the fastest band variant on the M0+, docs/device.md) with the level-3
// subtree index, no hole filling. Linked with
// -Wl,--defsym=__ram_budget=N, so the image does not link if its RAM (.data, .bss and the stack
// reserved for it) exceeds the target; run, it draws two cameras' frames, checks every band
// against the host's goldens and reports the stack's high-water mark and each part of its RAM.
#include <array>
#include <cstdint>

#include "targets/cortex-m/band_check.h"
#include "targets/cortex-m/semihosting.h"

using namespace octopoint;
using namespace octopoint::mcu;

namespace {

constexpr std::int32_t kWidth = 320;
constexpr Variant kVariant = Variant::kFixedDelta;
constexpr std::int32_t kRows = OCTOPOINT_BAND_ROWS;
constexpr std::size_t kIndexCapacity = 120;  // the default model has 398 nodes at tree level 4

// The renderer's state, all of it here (and the stack): what the RAM budget covers.
alignas(8) std::uint32_t band_buffer[static_cast<std::size_t>(kRows) * kWidth];
std::array<SubtreeSize, kIndexCapacity> index_storage;
BandIndex band_index;
Rgb565Palette palette;
FrameSetup setup;

int caseNumber(int camera, std::int32_t rows) {
  for (int i = 0; i < kCaseCount; ++i) {
    const BandCase& c = kCases[static_cast<std::size_t>(i)];
    if (c.camera == camera && c.depth == 8 && !c.fill && c.band_rows == rows) return i;
  }
  return -1;
}

}  // namespace

int octopoint::mcu::programMain() {
  startInstructionClock();
  const ModelView& model = defaultModel();
  const LevelView& level = *model.levelOfDepth(8);
  palette = makeRgb565Palette(model, kBackground);
  band_index = buildBandIndex(level, deepestIndexLevel(level, kIndexCapacity), index_storage);
  const std::uint32_t setup_stack = stackHighWater();
  paintStack();  // from here on, the high-water mark is the frames' alone
  int failures = 0;
  for (const int camera : {0, 1}) {
    const int number = caseNumber(camera, kRows);
    if (number < 0 ||
        buildFrameSetup(kCameras[camera], 8, kDefaultFractionBits, &setup) != CameraError::kNone) {
      return 1;
    }
    GoldenSink golden(number, kVariant, kWidth);
    const BandConfig config{kVariant, kRows, false, kBackground};
    const std::uint64_t start = instructionsNow();
    const BandError error = renderBands(level, setup, config, band_index, palette,
                                        {band_buffer, {}, {}}, golden.sink());
    const std::uint64_t spent = instructionsNow() - start - golden.flushInstructions();
    const bool passed = error == BandError::kNone && golden.passed();
    failures += passed ? 0 : 1;
    print(passed ? "pass" : "FAIL");
    print(" camera ");
    printUnsigned(static_cast<std::uint64_t>(camera));
    report(" instructions", spent);
  }
  report("band rows", kRows);
  report("index level", static_cast<std::uint64_t>(band_index.level));
  report("ram band buffer bytes", sizeof band_buffer);
  report("ram index bytes", band_index.sizes.size() * sizeof(SubtreeSize));
  report("ram index storage bytes", sizeof index_storage);
  report("ram palette bytes", sizeof palette);
  report("ram frame setup bytes", sizeof setup);
  report("ram model view bytes", sizeof(ModelView));
  return finishBudgetReport(setup_stack, failures);
}
