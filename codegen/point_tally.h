#pragma once
// What the streamed preparer learns of a scan's points as it reads them
// (codegen/streamed_prepare.h): the bounds of the points kept, in the model's axes; the
// intensities; the brightest colour channel; how many are finite. Each worker tallies the chunks it
// reads; the tallies are merged.

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "codegen/cube_fit.h"
#include "codegen/intensity_grey.h"
#include "codegen/point_source.h"
#include "codegen/prepare.h"

namespace octopoint::prepare {

// The points that go into the model, turned into its axes: inside the crop box (compared in the
// scan's own axes, as cropScan does), y-up turned by 180 degrees about x. The caller checks that
// they are finite.
class PointFilter {
 public:
  PointFilter(const std::optional<CropBox>& crop, ScanAxes axes, bool float_coordinates);

  bool keep(std::array<double, 3>& p) const {
    if (crop_) {
      for (std::size_t axis = 0; axis < 3; ++axis) {
        if (!(p[axis] >= low_[axis] && p[axis] <= high_[axis])) return false;
      }
    }
    if (axes_ == ScanAxes::kYUp) p = {p[0], -p[1], -p[2]};  // a rotation: no mirror image
    return true;
  }

 private:
  bool crop_;
  ScanAxes axes_;
  std::array<double, 3> low_{};
  std::array<double, 3> high_{};
};

inline bool isFinite(const std::array<double, 3>& p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

// Intensities that are integers 0..65535 (LAS), counted exactly in one pass: the range is the one
// IntensityPercentiles finds in two passes (the same nearest-rank 1st and 99th percentiles of the
// same values; for integers the float order is the integer order). 512 kB once started.
class ExactIntensity {
 public:
  void start() { counts_.assign(std::size_t{1} << 16, 0); }
  bool started() const { return !counts_.empty(); }
  void add(float v) { ++counts_[static_cast<std::uint16_t>(v)]; }
  void merge(const ExactIntensity& other);
  IntensityRange range() const;  // {0, 0} when nothing was counted

 private:
  std::vector<std::uint64_t> counts_;
};

// One worker's tally, and after merge() all of them.
struct PointTally {
  Bounds bounds;                        // of the points kept (cropped, turned)
  IntensityPercentiles intensity;       // the coarse counts of the two-pass percentiles
  ExactIntensity exact_intensity;       // instead, for 16-bit intensities read in one pass
  std::uint16_t brightest_channel = 0;  // the largest colour channel value seen
  std::uint64_t finite = 0;

  // Tallies the finite points of `chunk`, records from `first` of a source like `info` (named
  // `path` in messages; one beyond info.coordinate_limit is refused), the intensities into the
  // coarse counts if `coarse_intensity`, into the exact ones once started. The points are left as
  // read. Returns the chunk's brightest colour channel.
  std::uint16_t add(const PointChunk& chunk, std::uint64_t first, const SourceInfo& info,
                    const PointFilter& filter, bool coarse_intensity, const std::string& path);
  void merge(const PointTally& other);
};

}  // namespace octopoint::prepare
