#pragma once
// The view sweep's outputs (docs/tradeoff.md): one CSV row per cell and configuration, and a
// markdown page with the table and the any-size targets checked from the same numbers.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "lab/tradeoff.h"

namespace octopoint::tradeoff {

enum class Config {
  kBefore,        // today's renderer: finest depth, one pixel per voxel, no filling
  kBeforeFilled,  // the same with scanline hole filling
  kAfter,         // depth auto, footprint splats, no filling
  kAfterSmooth,   // the same with smooth splats (octopoint/smooth.h)
};
const char* configName(Config config);

struct SweepResult {
  Config config;
  int depth = 0;          // the depth drawn
  int splat_columns = 1;  // the most pixels a leaf covers along x (1: one pixel per leaf)
  int splat_rows = 1;     // and along y
  double ms_per_frame = 0;
  Quality quality;
  // PSNR of the reference in the colours of the model this configuration draws
  // (lab/palette_ceiling.h): no frame of that model can score more.
  double palette_ceiling_psnr = 0;
  // PSNR of the exact cover of the finest level of that model (lab/voxel_cover.h): what its
  // voxels show when each covers exactly the pixel centres inside its projection.
  double voxel_cover_psnr = 0;
  double voxel_cover_ssim = 0;  // and its SSIM
};

struct SweepCell {
  int width = 0, height = 0;
  double zoom = 1;
  std::vector<SweepResult> results;
  const SweepResult* find(Config config) const;
};

std::string sweepCsv(const std::string& label, const std::vector<SweepCell>& cells);
// The table (before / before + fill / after side by side per cell), box against smooth splats
// against the exact voxel cover (when the cells hold smooth results) and, when the cells hold
// "after" results, every any-size target (docs/tradeoff.md) with its measured numbers.
// `models` says what before and after draw (their depths and sizes), under the heading.
std::string sweepMarkdown(const std::string& label, const std::string& models,
                          const std::vector<SweepCell>& cells);

}  // namespace octopoint::tradeoff
