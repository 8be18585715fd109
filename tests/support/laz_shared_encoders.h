#pragma once
// What the tests' LAZ encoders of point-wise items (tests/support/laz_encoder.cpp) and of layered
// items (tests/support/laz_layered_encoder.cpp) share: the GPS time and colour coding, each the
// inverse of its decoder in codegen/.

#include <array>
#include <cstdint>

#include "codegen/laz_arithmetic.h"
#include "codegen/laz_integer.h"
#include "codegen/laz_layered_shared.h"
#include "codegen/laz_pointwise.h"
#include "codegen/laz_predictors.h"

// In octopoint::laz beside the decoders they invert (test support only: no library links it).
namespace octopoint::laz {

// a - b as the format's wrapping 32-bit arithmetic.
inline std::int32_t difference(std::int32_t a, std::int32_t b) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(a) - static_cast<std::uint32_t>(b));
}

// GPS times in up to four interleaved sequences, as GPSTIME11 version 2 codes them and POINT14
// version 3 (whose codes have no "unchanged": a flag of the point says whether the time changed).
class GpsTimeCoder {
 public:
  explicit GpsTimeCoder(bool version3)
      : zero_shift_(version3 ? 1 : 0),
        full_(version3 ? kGpsMultiCodeFull - 1 : kGpsMultiCodeFull),
        multi_(version3 ? kGpsMultiTotal - 1 : kGpsMultiTotal, false),
        zero_diff_(version3 ? 5 : 6, false) {}

  void start(std::int64_t first) {
    last_ = next_ = 0;
    diff_ = {};
    extreme_ = {};
    times_ = {first, 0, 0, 0};
    multi_.reset();
    zero_diff_.reset();
    time_.reset();
  }

  void encode(ArithmeticEncoder& e, std::int64_t time) {
    for (;;) {  // at most one switch of sequence: after it the time fits the new one
      if (encodeStep(e, time)) return;
    }
  }

 private:
  static bool fits32(std::int64_t diff) { return diff == static_cast<std::int32_t>(diff); }

  std::int64_t differenceTo(std::int64_t time, std::uint32_t sequence) const {
    return static_cast<std::int64_t>(static_cast<std::uint64_t>(time) -
                                     static_cast<std::uint64_t>(times_[sequence]));
  }

  // A time no sequence is near: a new sequence, its high half predicted, its low half raw.
  void startSequence(ArithmeticEncoder& e, std::int64_t time) {
    const auto bits = static_cast<std::uint64_t>(time);
    time_.encode(e, static_cast<std::int32_t>(static_cast<std::uint64_t>(times_[last_]) >> 32),
                 static_cast<std::int32_t>(bits >> 32), 8);
    e.writeInt(static_cast<std::uint32_t>(bits));
    next_ = (next_ + 1) & 3;
    last_ = next_;
    diff_[last_] = 0;
    extreme_[last_] = 0;
  }

  // The sequence among the other three that `time` is near, or 0.
  std::uint32_t otherSequence(std::int64_t time) const {
    for (std::uint32_t i = 1; i < 4; ++i) {
      if (fits32(differenceTo(time, (last_ + i) & 3))) return i;
    }
    return 0;
  }

  void noteExtreme(std::int32_t diff) {
    if (++extreme_[last_] > 3) {
      diff_[last_] = diff;
      extreme_[last_] = 0;
    }
  }

  bool encodeStep(ArithmeticEncoder& e, std::int64_t time) {
    const std::int64_t diff64 = differenceTo(time, last_);
    const auto diff = static_cast<std::int32_t>(diff64);
    const std::int32_t last_diff = diff_[last_];
    if (last_diff == 0) {
      if (diff64 == 0 && zero_shift_ == 0) {
        e.encodeSymbol(zero_diff_, 0);
        return true;
      }
      if (fits32(diff64)) {
        e.encodeSymbol(zero_diff_, 1 - zero_shift_);
        time_.encode(e, 0, diff, 0);
        diff_[last_] = diff;
        extreme_[last_] = 0;
      } else if (const std::uint32_t other = otherSequence(time)) {
        e.encodeSymbol(zero_diff_, other + 2 - zero_shift_);
        last_ = (last_ + other) & 3;
        return false;
      } else {
        e.encodeSymbol(zero_diff_, 2 - zero_shift_);
        startSequence(e, time);
      }
      times_[last_] = time;
      return true;
    }
    if (diff64 == 0 && zero_shift_ == 0) {
      e.encodeSymbol(multi_, kGpsMultiUnchanged);
      return true;
    }
    if (fits32(diff64)) {
      const float ratio = static_cast<float>(diff) / static_cast<float>(last_diff);
      const auto multi = static_cast<std::int32_t>(ratio >= 0 ? ratio + 0.5f : ratio - 0.5f);
      const auto times = [](std::int32_t a, std::int32_t b) {
        return static_cast<std::int32_t>(static_cast<std::uint32_t>(a) *
                                         static_cast<std::uint32_t>(b));
      };
      if (multi == 1) {
        e.encodeSymbol(multi_, 1);
        time_.encode(e, last_diff, diff, 1);
        extreme_[last_] = 0;
      } else if (multi > 0 && multi < kGpsMulti) {
        e.encodeSymbol(multi_, static_cast<std::uint32_t>(multi));
        time_.encode(e, times(multi, last_diff), diff, multi < 10 ? 2 : 3);
      } else if (multi > 0) {
        e.encodeSymbol(multi_, kGpsMulti);
        time_.encode(e, times(kGpsMulti, last_diff), diff, 4);
        noteExtreme(diff);
      } else if (multi < 0 && multi > kGpsMultiMinus) {
        e.encodeSymbol(multi_, static_cast<std::uint32_t>(kGpsMulti - multi));
        time_.encode(e, times(multi, last_diff), diff, 5);
      } else if (multi < 0) {
        e.encodeSymbol(multi_, static_cast<std::uint32_t>(kGpsMulti - kGpsMultiMinus));
        time_.encode(e, times(kGpsMultiMinus, last_diff), diff, 6);
        noteExtreme(diff);
      } else {
        e.encodeSymbol(multi_, 0);
        time_.encode(e, 0, diff, 7);
        noteExtreme(diff);
      }
    } else if (const std::uint32_t other = otherSequence(time)) {
      e.encodeSymbol(multi_, full_ + other);
      last_ = (last_ + other) & 3;
      return false;
    } else {
      e.encodeSymbol(multi_, full_);
      startSequence(e, time);
    }
    times_[last_] = time;
    return true;
  }

  std::uint32_t zero_shift_;  // version 3's codes are version 2's less one
  std::uint32_t full_;        // the code of a whole new time
  std::uint32_t last_ = 0;
  std::uint32_t next_ = 0;
  std::array<std::int64_t, 4> times_{};
  std::array<std::int32_t, 4> diff_{};
  std::array<std::int32_t, 4> extreme_{};
  SymbolModel multi_;
  SymbolModel zero_diff_;
  IntegerModels time_{32, 9, false};
};

// The colour coded from the last (codegen/laz_shared_items.h decodeRgb is its inverse).
void encodeRgb(ArithmeticEncoder& e, RgbModels& models, const std::uint8_t* last,
               const std::uint8_t* item);

}  // namespace octopoint::laz
