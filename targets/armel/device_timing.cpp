// device_timing: Table 2 of the paper on the CPU this is built for. Renders the embedded default
// model frontal and rotated with every render variant at depths 7 and 8, prints the milliseconds
// per image, and for every algorithm the float/fixed ratio (float_X against fixed_X). Built for
// the `armel` preset it runs under qemu-arm, an ARMv5TE without FPU (docs/device.md). Integer
// arithmetic only, so the tool itself does not perturb a soft-float device.
#include <algorithm>
#include <array>
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cli/arguments.h"
#include "cli/numbers.h"
#include "cli/run_tool.h"
#include "octopoint/models.h"
#include "octopoint/render.h"

namespace octopoint {
namespace {

constexpr int kRuns = 5;  // the reported time is the median over runs
constexpr std::array kDepths = {7, 8};
struct View {
  const char* name;
  int yaw_degrees;
};
constexpr std::array kViews = {View{"frontal", 0}, View{"rotated", 30}};
constexpr std::string_view kFixedPrefix = "fixed_";
constexpr std::string_view kFloatPrefix = "float_";

constexpr const char* kUsage =
    "usage: device_timing [--size WxH] [--min-ms N]\n"
    "Renders the embedded default model frontal (yaw 0) and rotated (yaw 30 degrees) with every\n"
    "render variant at depths 7 and 8 and prints a table of CPU milliseconds per image (frame "
    "clear\n"
    "included; median of 5 runs) and the float/fixed ratio of each algorithm (float_X vs "
    "fixed_X).\n"
    "  --size WxH   framebuffer size in pixels, each side 1..8192, at most 16777216 pixels\n"
    "               (default 320x240)\n"
    "  --min-ms N   time spent per table cell, 1..3600000, at least one frame per run (default "
    "500)\n";

struct Options {
  std::int32_t width = 320;
  std::int32_t height = 240;
  std::int64_t min_ms = 500;
};

Options parseOptions(int argc, char** argv) {
  Options options;
  cli::ArgumentReader args(argc, argv);
  while (args.next()) {
    if (args.is("-h") || args.is("--help")) {
      std::fputs(kUsage, stdout);
      std::exit(0);
    } else if (args.is("--min-ms")) {
      options.min_ms = cli::parseInteger(args.name(), args.value(), 1, 3'600'000);
    } else if (args.is("--size")) {
      const cli::FrameSize size = cli::parseFrameSize(args.name(), args.value(), 1,
                                                      kMaxViewportSide, std::int64_t{4096} * 4096);
      options.width = size.width;
      options.height = size.height;
    } else {
      args.refuseUnknown();
    }
  }
  return options;
}

// CPU time of this thread in nanoseconds. CPU time rather than wall time: the machine is shared,
// and under qemu-arm this is the emulating host thread's time, which waiting does not inflate.
std::int64_t threadCpuNs() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return std::int64_t{now.tv_sec} * 1'000'000'000 + now.tv_nsec;
}

// CPU nanoseconds per frame (clear + decode), the median of kRuns runs of at least min_ms / kRuns;
// -1 when the variant refuses to draw the level.
std::int64_t timeFrames(Variant variant, const LevelView& level, const FrameSetup& setup,
                        Framebuffer& frame, std::int64_t min_ms) {
  const std::int64_t run_ns = min_ms * 1'000'000 / kRuns;
  frame.clear();
  // Warm-up: caches, page faults, qemu's translation.
  if (!renderLevel(variant, level, setup, frame)) return -1;
  std::array<std::int64_t, kRuns> per_frame_ns{};
  for (std::int64_t& result : per_frame_ns) {
    const std::int64_t start = threadCpuNs();
    std::int64_t frames = 0;
    std::int64_t elapsed = 0;
    do {
      frame.clear();
      static_cast<void>(renderLevel(variant, level, setup, frame));  // the warm-up drew it
      ++frames;
      elapsed = threadCpuNs() - start;
    } while (elapsed < run_ns);
    result = elapsed / frames;
  }
  std::sort(per_frame_ns.begin(), per_frame_ns.end());
  return per_frame_ns[kRuns / 2];
}

// "12.34": milliseconds with two decimals, from nanoseconds, in integer arithmetic.
std::string formatMs(std::int64_t ns) {
  const std::int64_t hundredths = (ns + 5'000) / 10'000;
  char text[32];
  std::snprintf(text, sizeof text, "%" PRId64 ".%02" PRId64, hundredths / 100, hundredths % 100);
  return text;
}

// "6.1x": numerator / denominator with one decimal, rounded.
std::string formatRatio(std::int64_t numerator, std::int64_t denominator) {
  const std::int64_t tenths = (20 * numerator + denominator) / (2 * denominator);
  char text[32];
  std::snprintf(text, sizeof text, "%" PRId64 ".%" PRId64 "x", tenths / 10, tenths % 10);
  return text;
}

struct Row {
  std::string_view variant;
  std::vector<std::int64_t> ns;  // one per (depth, view) column
};

const Row* findRow(const std::vector<Row>& rows, std::string_view variant) {
  const auto found = std::find_if(rows.begin(), rows.end(),
                                  [&](const Row& row) { return row.variant == variant; });
  return found == rows.end() ? nullptr : &*found;
}

// The fastest float variant against the fastest fixed one, per column: what a device gains by
// choosing fixed point, whatever the algorithm.
void printBestRatio(const std::vector<Row>& rows) {
  std::printf("| best float / best fixed |");
  for (std::size_t column = 0; column < rows.front().ns.size(); ++column) {
    std::int64_t best[2] = {INT64_MAX, INT64_MAX};  // [0] fixed, [1] float
    for (const Row& row : rows) {
      const bool is_float = row.variant.starts_with(kFloatPrefix);
      if (is_float || row.variant.starts_with(kFixedPrefix)) {
        best[is_float] = std::min(best[is_float], row.ns[column]);
      }
    }
    std::printf(" %s |", best[1] == INT64_MAX ? "no float variant yet"
                                              : formatRatio(best[1], best[0]).c_str());
  }
  std::printf("\n");
}

// The time table, then the float/fixed ratio table, under the same columns.
void printTables(const std::vector<Row>& rows, const std::string& columns,
                 const std::string& rule) {
  std::printf("| variant |%s\n%s\n", columns.c_str(), rule.c_str());
  for (const Row& row : rows) {
    std::printf("| %.*s |", static_cast<int>(row.variant.size()), row.variant.data());
    for (std::int64_t ns : row.ns) std::printf(" %s |", formatMs(ns).c_str());
    std::printf("\n");
  }

  std::printf(
      "\nfloat/fixed time ratio per algorithm (float_X ms / fixed_X ms; higher: fixed wins "
      "more)\n\n");
  std::printf("| algorithm |%s\n%s\n", columns.c_str(), rule.c_str());
  for (const Row& fixed : rows) {
    if (!fixed.variant.starts_with(kFixedPrefix)) continue;
    const std::string_view algorithm = fixed.variant.substr(kFixedPrefix.size());
    std::printf("| %.*s |", static_cast<int>(algorithm.size()), algorithm.data());
    const Row* floating = findRow(rows, std::string(kFloatPrefix) + std::string(algorithm));
    if (floating == nullptr) {
      std::printf(" no float variant yet |\n");
      continue;
    }
    for (std::size_t column = 0; column < fixed.ns.size(); ++column) {
      std::printf(" %s |", formatRatio(floating->ns[column], fixed.ns[column]).c_str());
    }
    std::printf("\n");
  }
}

int run(const Options& options) {
  ModelIssue issue;
  const EmbeddedModel& embedded = *models::defaultModel();
  const std::optional<ModelView> model = ModelView::fromEmbedded(embedded, &issue);
  if (!model) {
    std::fprintf(stderr, "device_timing: the embedded model '%s' is invalid: %s\n", embedded.name,
                 describe(issue.error));
    return 1;
  }
  std::printf(
      "Default model '%s' at %dx%d, CPU ms per image (frame clear included, median of %d runs)\n\n",
      embedded.name, options.width, options.height, kRuns);
  std::string columns;
  std::string rule = "|---|";
  for (int depth : kDepths) {
    const LevelView* level = model->levelOfDepth(depth);
    for (const View& view : kViews) {
      columns += " depth " + std::to_string(depth) + " " + view.name +
                 (level ? " (" + std::to_string(level->leaves.size()) + " points) |" : " |");
      rule += "---|";
    }
  }

  Framebuffer frame(options.width, options.height);
  std::vector<Row> rows;
  for (const VariantInfo& info : allVariants()) {
    Row row{info.name, {}};
    for (int depth : kDepths) {
      const LevelView* level = model->levelOfDepth(depth);
      if (level == nullptr) {
        std::fprintf(stderr, "device_timing: the model '%s' has no depth %d\n", embedded.name,
                     depth);
        return 1;
      }
      for (const View& view : kViews) {
        Camera camera;
        camera.width = options.width;
        camera.height = options.height;
        camera.yaw = Angle::fromDegrees(view.yaw_degrees);
        FrameSetup setup;
        if (const CameraError error = buildFrameSetup(camera, depth, kDefaultFractionBits, &setup);
            error != CameraError::kNone) {
          std::fprintf(stderr, "device_timing: camera refused: %s\n", describe(error));
          return 1;
        }
        row.ns.push_back(timeFrames(info.variant, *level, setup, frame, options.min_ms));
        if (row.ns.back() < 0) {
          std::fprintf(stderr, "device_timing: %.*s refused to draw\n",
                       static_cast<int>(info.name.size()), info.name.data());
          return 1;
        }
      }
    }
    rows.push_back(std::move(row));
  }

  printTables(rows, columns, rule);
  printBestRatio(rows);
  return 0;
}

}  // namespace
}  // namespace octopoint

int main(int argc, char** argv) {
  return octopoint::cli::runTool("device_timing", argc, argv, [](int count, char** values) {
    return octopoint::run(octopoint::parseOptions(count, values));
  });
}
