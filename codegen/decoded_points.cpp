#include "codegen/decoded_points.h"

namespace octopoint::prepare {
namespace {

constexpr std::uint64_t kXyzBytes = sizeof(std::array<double, 3>);
constexpr std::uint64_t kRgbBytes = sizeof(std::array<std::uint16_t, 3>);
constexpr std::uint64_t kIntensityBytes = sizeof(float);

}  // namespace

DecodedPoints::DecodedPoints(const std::filesystem::path& temp_dir, std::size_t pieces)
    : file_(temp_dir), pieces_(pieces) {}

std::uint64_t DecodedPoints::bytesFor(const SourceInfo& info, std::uint64_t points) {
  const bool intensity = info.payload == PointPayload::kIntensity || info.has_intensity;
  const std::uint64_t per_point = kXyzBytes + (info.payload == PointPayload::kRgb ? kRgbBytes : 0) +
                                  (intensity ? kIntensityBytes : 0);
  return points * per_point;
}

void DecodedPoints::keep(std::size_t piece, const PointChunk& chunk) {
  const std::size_t count = chunk.xyz.size();
  Piece& kept = pieces_.at(piece);
  kept.count = count;
  kept.rgb = !chunk.rgb.empty();
  kept.intensity = !chunk.intensity.empty();
  const std::uint64_t xyz = count * kXyzBytes;
  const std::uint64_t rgb = kept.rgb ? count * kRgbBytes : 0;
  const std::uint64_t intensity = kept.intensity ? count * kIntensityBytes : 0;
  kept.offset = file_.reserve(xyz + rgb + intensity);
  file_.writeAt(kept.offset, chunk.xyz.data(), xyz);
  if (rgb) file_.writeAt(kept.offset + xyz, chunk.rgb.data(), rgb);
  if (intensity) file_.writeAt(kept.offset + xyz + rgb, chunk.intensity.data(), intensity);
}

void DecodedPoints::read(std::size_t piece, PointChunk& chunk) const {
  const Piece& kept = pieces_.at(piece);
  chunk.xyz.resize(kept.count);
  chunk.rgb.resize(kept.rgb ? kept.count : 0);
  chunk.intensity.resize(kept.intensity ? kept.count : 0);
  const std::uint64_t xyz = kept.count * kXyzBytes;
  const std::uint64_t rgb = kept.rgb ? kept.count * kRgbBytes : 0;
  file_.readAt(kept.offset, chunk.xyz.data(), xyz);
  if (kept.rgb) file_.readAt(kept.offset + xyz, chunk.rgb.data(), rgb);
  if (kept.intensity) {
    file_.readAt(kept.offset + xyz + rgb, chunk.intensity.data(), kept.count * kIntensityBytes);
  }
}

}  // namespace octopoint::prepare
