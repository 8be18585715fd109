#pragma once
// What both bare-metal programs share: the model set up once at boot, and a band sink that
// checksums every flushed band against the host's goldens (targets/cortex-m/golden_main.cpp).

#include <cstdint>
#include <optional>
#include <span>

#include "octopoint/bands.h"
#include "targets/cortex-m/band_cases.h"

namespace octopoint::mcu {

// Compares flushed bands with the golden bands of one case, as `variant` draws it (with or
// without footprint splats). A flushed band may span several golden bands (a taller band than the
// case's): it is checked slice by slice.
class GoldenSink {
 public:
  GoldenSink(int case_number, Variant variant, std::int32_t width);
  // Against the golden bands from `golden` on, each `golden_rows` high, of a frame of width x
  // height.
  GoldenSink(const std::uint32_t* golden, std::int32_t golden_rows, std::int32_t width,
             std::int32_t height);
  BandSink sink();
  bool passed() const { return mismatches_ == 0 && next_y0_ == height_; }
  // Instructions spent in flush (checksumming): the display driver's time, not the renderer's.
  std::uint64_t flushInstructions() const { return flush_instructions_; }

 private:
  static void flush(void* user, std::int32_t y0, std::int32_t rows,
                    std::span<const std::uint8_t> rgb565);

  const std::uint32_t* golden_;
  std::int32_t golden_rows_;
  std::int32_t width_;
  std::int32_t height_;
  std::int32_t next_y0_ = 0;
  int mismatches_ = 0;
  std::uint64_t flush_instructions_ = 0;
};

// The default model, validated at boot (set-up, not per frame).
const ModelView& defaultModel();

// Prints "label value\n".
void report(const char* label, std::uint64_t value);

// The end of a RAM budget image's report: the stack's high-water marks (`setup_stack` before the
// frames), its region, the static RAM and the peak and linked totals, and `failures`; returns the
// program's status: 0 when nothing failed and the stack stayed inside its region.
int finishBudgetReport(std::uint32_t setup_stack, int failures);

}  // namespace octopoint::mcu
