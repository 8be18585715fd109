#pragma once
// The normal palette of a model (format version 2, octopoint/model.h): at most 255 unit
// vectors in Q1.14, and each voxel's normal stored as the index of the nearest one.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace octopoint::prepare {

using Normal3f = std::array<float, 3>;
using NormalQ14 = std::array<std::int16_t, 3>;

inline constexpr int kNormalPaletteEntries = 255;  // format::kMaxNormals

enum class NormalPaletteKind {
  kLattice,   // a fixed spherical Fibonacci lattice: the same for every model
  kAdaptive,  // spread over the model's normals (farthest points), refined by Lloyd (k-means)
              // passes
};

class NormalPalette {
 public:
  // The palette for a model whose voxels have `normals` (unit vectors).
  static NormalPalette build(std::span<const Normal3f> normals, NormalPaletteKind kind,
                             int entries = kNormalPaletteEntries);

  // Unit vectors, rounded to Q1.14 (2^14 = 1.0).
  const std::vector<NormalQ14>& entries() const { return entries_; }
  // The index of the entry nearest to `normal` (largest dot product).
  std::uint8_t indexOf(const Normal3f& normal) const;
  // The angle between `normal` and its entry, in degrees.
  double errorDegrees(const Normal3f& normal) const;

 private:
  std::vector<NormalQ14> entries_;
  std::vector<Normal3f> unit_;  // the entries as floats, for the search
};

// `count` directions spread evenly over the sphere (spherical Fibonacci lattice).
std::vector<Normal3f> fibonacciSphere(int count);

}  // namespace octopoint::prepare
