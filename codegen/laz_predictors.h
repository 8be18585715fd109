#pragma once
// The predictors and contexts that the LAZ point-wise items share between their encoder and their
// decoder (codegen/laz_pointwise.cpp, tests/support/laz_encoder.cpp): both must compute them alike.

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace octopoint::laz {

// Little-endian fields of a record (every host we build for is little-endian, as LAS is).
template <typename T>
T load(const std::uint8_t* at) {
  T value;
  std::memcpy(&value, at, sizeof value);
  return value;
}

template <typename T>
void store(std::uint8_t* at, T value) {
  std::memcpy(at, &value, sizeof value);
}

// POINT10's fields (LAS "Point Data Record Format 0").
inline constexpr std::size_t kX = 0, kY = 4, kZ = 8, kIntensity = 12, kFlags = 14, kClass = 15,
                             kScanAngle = 16, kUserData = 17, kSourceId = 18, kPoint10Bytes = 20;

inline std::uint32_t returnNumber(std::uint8_t flags) { return flags & 7u; }
inline std::uint32_t returnCount(std::uint8_t flags) { return (flags >> 3) & 7u; }
inline std::uint32_t scanDirection(std::uint8_t flags) { return (flags >> 6) & 1u; }

inline std::uint8_t foldByte(std::int32_t value) {
  return static_cast<std::uint8_t>(value);
}  // mod 256
inline std::int32_t clampByte(std::int32_t value) {
  return value < 0 ? 0 : value > 255 ? 255 : value;
}

inline std::uint32_t evenBelow(std::uint32_t k) { return k & ~1u; }

// Contexts by (number of returns, return number): the 15 valid pairs get their own, the rest share
// ones that keep files with swapped or zero-based fields compressing well.
inline constexpr std::uint8_t kReturnContext[8][8] = {
    {15, 14, 13, 12, 11, 10, 9, 8},  {14, 0, 1, 3, 6, 10, 10, 9},
    {13, 1, 2, 4, 7, 11, 11, 10},    {12, 3, 4, 5, 8, 12, 12, 11},
    {11, 6, 7, 8, 9, 13, 13, 12},    {10, 10, 11, 12, 13, 14, 14, 13},
    {9, 10, 11, 12, 13, 14, 15, 14}, {8, 9, 10, 11, 12, 13, 14, 15}};

// The height context: how far a return is from the last of its pulse.
inline std::uint32_t returnLevel(std::uint32_t count, std::uint32_t number) {
  return count > number ? count - number : number - count;
}

// The median of the last five values, kept sorted as they arrive (the insertion alternates between
// the high and the low end, so that the oldest values leave first on either side).
class Median5 {
 public:
  void reset() {
    values_ = {};
    high_ = true;
  }
  std::int32_t get() const { return values_[2]; }
  void add(std::int32_t v) {
    auto& s = values_;
    if (high_) {
      if (v < s[2]) {
        s[4] = s[3];
        s[3] = s[2];
        if (v < s[0]) {
          s[2] = s[1];
          s[1] = s[0];
          s[0] = v;
        } else if (v < s[1]) {
          s[2] = s[1];
          s[1] = v;
        } else {
          s[2] = v;
        }
      } else {
        if (v < s[3]) {
          s[4] = s[3];
          s[3] = v;
        } else {
          s[4] = v;
        }
        high_ = false;
      }
    } else {
      if (s[2] < v) {
        s[0] = s[1];
        s[1] = s[2];
        if (s[4] < v) {
          s[2] = s[3];
          s[3] = s[4];
          s[4] = v;
        } else if (s[3] < v) {
          s[2] = s[3];
          s[3] = v;
        } else {
          s[2] = v;
        }
      } else {
        if (s[1] < v) {
          s[0] = s[1];
          s[1] = v;
        } else {
          s[0] = v;
        }
        high_ = true;
      }
    }
  }

 private:
  std::array<std::int32_t, 5> values_{};
  bool high_ = true;
};

// GPSTIME11 version 2's multipliers of the last time difference: 1 to kGpsMulti - 1 as they are,
// kGpsMulti for larger ones, then the negative ones down to kGpsMultiMinus, and codes beyond.
inline constexpr std::int32_t kGpsMulti = 500;
inline constexpr std::int32_t kGpsMultiMinus = -10;
inline constexpr std::uint32_t kGpsMultiUnchanged = kGpsMulti - kGpsMultiMinus + 1;
inline constexpr std::uint32_t kGpsMultiCodeFull = kGpsMulti - kGpsMultiMinus + 2;
inline constexpr std::uint32_t kGpsMultiTotal = kGpsMulti - kGpsMultiMinus + 6;

}  // namespace octopoint::laz
