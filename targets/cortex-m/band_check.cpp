#include "targets/cortex-m/band_check.h"

#include "mcu/golden.h"
#include "octopoint/models.h"
#include "targets/cortex-m/semihosting.h"

extern "C" std::uint32_t __data_start[],
    __stack_bottom[];  // targets/cortex-m/sections.ld: RAM's start, static end

namespace octopoint::mcu {

GoldenSink::GoldenSink(int case_number, Variant variant, std::int32_t width)
    : GoldenSink((drawsSplats(variant) ? kGoldenSplatBands : kGoldenPixelBands) +
                     kGoldenFirst[case_number],
                 kCases[static_cast<std::size_t>(case_number)].band_rows, width,
                 kCameras[kCases[static_cast<std::size_t>(case_number)].camera].height) {}

GoldenSink::GoldenSink(const std::uint32_t* golden, std::int32_t golden_rows, std::int32_t width,
                       std::int32_t height)
    : golden_(golden), golden_rows_(golden_rows), width_(width), height_(height) {}

BandSink GoldenSink::sink() {
  BandSink sink;
  sink.user = this;
  sink.flush = &GoldenSink::flush;
  return sink;
}

void GoldenSink::flush(void* user, std::int32_t y0, std::int32_t rows,
                       std::span<const std::uint8_t> rgb565) {
  const std::uint64_t start = instructionsNow();
  auto& self = *static_cast<GoldenSink*>(user);
  if (y0 != self.next_y0_) ++self.mismatches_;
  self.next_y0_ = y0 + rows;
  const std::size_t row_bytes = static_cast<std::size_t>(self.width_) * 2;
  // The golden band that starts at y0: bands are in order, so step to it.
  for (std::int32_t at = 0; at < rows;) {
    const std::int32_t slice = rows - at < self.golden_rows_ ? rows - at : self.golden_rows_;
    const std::uint32_t sum =
        checksum(kChecksumSeed, rgb565.data() + static_cast<std::size_t>(at) * row_bytes,
                 static_cast<std::size_t>(slice) * row_bytes);
    if (sum != *self.golden_++) ++self.mismatches_;
    at += slice;
  }
  self.flush_instructions_ += instructionsNow() - start;
}

const ModelView& defaultModel() {
  static std::optional<ModelView> model;
  if (!model) {
    ModelIssue issue;
    model = ModelView::fromEmbedded(*models::defaultModel(), &issue);
    if (!model) {
      print("the default model does not validate\n");
      exitProgram(false);
    }
  }
  return *model;
}

void report(const char* label, std::uint64_t value) {
  print(label);
  print(" ");
  printUnsigned(value);
  print("\n");
}

int finishBudgetReport(std::uint32_t setup_stack, int failures) {
  report("stack high-water bytes (set-up: model validation, index)", setup_stack);
  report("stack high-water bytes", stackHighWater());
  report("stack region bytes", stackBytes());
  const auto static_bytes =
      static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(__stack_bottom) -
                                 reinterpret_cast<std::uintptr_t>(__data_start));
  report("ram static bytes (.data + .bss)", static_bytes);
  report("ram peak bytes (static + stack high-water)", static_bytes + stackHighWater());
  report("ram linked bytes (static + stack region)", static_bytes + stackBytes());
  report("failures", static_cast<std::uint64_t>(failures));
  return failures == 0 && stackHighWater() < stackBytes() ? 0 : 1;
}

}  // namespace octopoint::mcu
