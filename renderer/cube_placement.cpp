// The cube's placement (octopoint/model.h): checked on the bits of its binary64 numbers, with
// integer operations only, so that the device builds read it without a soft-float helper.
#include "renderer/cube_placement.h"

#include "renderer/little_endian.h"

namespace octopoint {
namespace {

constexpr std::uint64_t kExponentMask = std::uint64_t{0x7FF} << 52;
constexpr std::uint64_t kSignBit = std::uint64_t{1} << 63;

// Not infinite, not NaN: the exponent field is not all ones.
bool finite(std::uint64_t bits) { return (bits & kExponentMask) != kExponentMask; }

}  // namespace

bool validCubePlacement(const CubePlacement& cube) {
  if (!cube.recorded()) {
    return cube.corner_bits[0] == 0 && cube.corner_bits[1] == 0 && cube.corner_bits[2] == 0 &&
           cube.scan_axes == format::kScanAxesYDown;
  }
  for (std::uint64_t corner : cube.corner_bits) {
    if (!finite(corner)) return false;
  }
  // An edge above 0: positive sign, not +0 (recorded() saw that), finite.
  if ((cube.edge_bits & kSignBit) != 0 || !finite(cube.edge_bits)) return false;
  return cube.scan_axes == format::kScanAxesYDown || cube.scan_axes == format::kScanAxesYUp;
}

bool readCubePlacement(const std::uint8_t* p, CubePlacement* cube) {
  for (int axis = 0; axis < 3; ++axis) cube->corner_bits[axis] = le::readU64(p + 8 * axis);
  cube->edge_bits = le::readU64(p + 24);
  cube->scan_axes = p[32];
  for (int at = 33; at < static_cast<int>(format::kCubePlacementBytes); ++at) {
    if (p[at] != 0) return false;
  }
  return validCubePlacement(*cube);
}

}  // namespace octopoint
