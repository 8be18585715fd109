// The point-wise LAZ item decoders (codegen/laz_pointwise.h), written from the LAZ specification's
// description of each item's predictions and contexts. All coordinate and time arithmetic wraps in
// uint32/uint64 as the format's two's complement values do.

#include "codegen/laz_pointwise.h"

#include <array>
#include <cstring>
#include <vector>

#include "codegen/laz_integer.h"
#include "codegen/laz_predictors.h"

namespace octopoint::laz {
namespace {

// A byte per context, each with its own 256-symbol model made on first use.
class ByteModels {
 public:
  std::uint8_t decode(ArithmeticDecoder& decoder, std::uint8_t context) {
    std::unique_ptr<SymbolModel>& model = models_[context];
    if (!model) model = std::make_unique<SymbolModel>(256);
    return static_cast<std::uint8_t>(decoder.decodeSymbol(*model));
  }
  void reset() {
    for (auto& model : models_)
      if (model) model->reset();
  }

 private:
  std::array<std::unique_ptr<SymbolModel>, 256> models_;
};

std::int32_t addWrapping(std::int32_t a, std::int32_t b) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(a) + static_cast<std::uint32_t>(b));
}
std::int32_t mulWrapping(std::int32_t a, std::int32_t b) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(a) * static_cast<std::uint32_t>(b));
}

// POINT10 version 2: a symbol says which of the other fields changed; x and y are predicted by the
// median of the last five differences of the same return context, z by the last z of the same
// return level.
class Point10V2 final : public ItemDecoder {
 public:
  explicit Point10V2(ArithmeticDecoder& decoder) : shared_(decoder) {}

  void start(const std::uint8_t* first) override {
    for (auto& m : x_median_) m.reset();
    for (auto& m : y_median_) m.reset();
    last_intensity_ = {};
    last_height_ = {};
    changed_.reset();
    intensity_.reset();
    for (auto& m : scan_angle_) m.reset();
    source_id_.reset();
    flags_.reset();
    classes_.reset();
    user_data_.reset();
    dx_.reset();
    dy_.reset();
    z_.reset();
    std::memcpy(last_.data(), first, kPoint10Bytes);
    store<std::uint16_t>(&last_[kIntensity], 0);  // intensities are predicted per return context
  }

  void decode(std::uint8_t* item) override {
    ArithmeticDecoder d = shared_;  // in registers for the point (codegen/laz_arithmetic.h)
    std::uint8_t* last = last_.data();
    const std::uint32_t changed = d.decodeSymbol(changed_);
    if (changed & 32) last[kFlags] = flags_.decode(d, last[kFlags]);
    const std::uint32_t number = returnNumber(last[kFlags]);
    const std::uint32_t count = returnCount(last[kFlags]);
    const std::uint32_t m = kReturnContext[count][number];
    const std::uint32_t level = returnLevel(count, number);
    if (changed & 16) {
      last_intensity_[m] =
          static_cast<std::uint16_t>(intensity_.decode(d, last_intensity_[m], m < 3 ? m : 3));
    }
    // A point with nothing changed keeps the last point's intensity, whatever its context's.
    if (changed) store<std::uint16_t>(&last[kIntensity], last_intensity_[m]);
    if (changed & 8) last[kClass] = classes_.decode(d, last[kClass]);
    if (changed & 4) {
      const std::uint32_t delta = d.decodeSymbol(scan_angle_[scanDirection(last[kFlags])]);
      last[kScanAngle] = foldByte(static_cast<std::int32_t>(delta) + last[kScanAngle]);
    }
    if (changed & 2) last[kUserData] = user_data_.decode(d, last[kUserData]);
    if (changed & 1) {
      store<std::uint16_t>(&last[kSourceId], static_cast<std::uint16_t>(source_id_.decode(
                                                 d, load<std::uint16_t>(&last[kSourceId]), 0)));
    }
    const std::uint32_t single = count == 1;
    const std::int32_t dx = dx_.decode(d, x_median_[m].get(), single);
    store(&last[kX], addWrapping(load<std::int32_t>(&last[kX]), dx));
    x_median_[m].add(dx);
    std::uint32_t k = dx_.k();
    const std::int32_t dy =
        dy_.decode(d, y_median_[m].get(), single + (k < 20 ? evenBelow(k) : 20));
    store(&last[kY], addWrapping(load<std::int32_t>(&last[kY]), dy));
    y_median_[m].add(dy);
    k = (dx_.k() + dy_.k()) / 2;
    const std::int32_t z = z_.decode(d, last_height_[level], single + (k < 18 ? evenBelow(k) : 18));
    store(&last[kZ], z);
    last_height_[level] = z;
    std::memcpy(item, last, kPoint10Bytes);
    shared_ = d;
  }

 private:
  ArithmeticDecoder& shared_;  // the chunk's decoder, copied in and out by decode()
  std::array<std::uint8_t, kPoint10Bytes> last_{};
  std::array<Median5, 16> x_median_, y_median_;
  std::array<std::uint16_t, 16> last_intensity_{};
  std::array<std::int32_t, 8> last_height_{};
  SymbolModel changed_{64};
  IntegerModels intensity_{16, 4};
  std::array<SymbolModel, 2> scan_angle_{SymbolModel(256), SymbolModel(256)};
  IntegerModels source_id_{16, 1};
  ByteModels flags_, classes_, user_data_;
  IntegerModels dx_{32, 2}, dy_{32, 22}, z_{32, 20};
};

// POINT10 version 1: x and y predicted by the median of the last three differences, z by the last
// z, the other fields after the coordinates.
class Point10V1 final : public ItemDecoder {
 public:
  explicit Point10V1(ArithmeticDecoder& decoder) : shared_(decoder) {}

  void start(const std::uint8_t* first) override {
    x_diffs_ = {};
    y_diffs_ = {};
    next_ = 0;
    dx_.reset();
    dy_.reset();
    z_.reset();
    intensity_.reset();
    scan_angle_.reset();
    source_id_.reset();
    changed_.reset();
    flags_.reset();
    classes_.reset();
    user_data_.reset();
    std::memcpy(last_.data(), first, kPoint10Bytes);
  }

  void decode(std::uint8_t* item) override {
    ArithmeticDecoder d = shared_;  // in registers for the point (codegen/laz_arithmetic.h)
    std::uint8_t* last = last_.data();
    const std::int32_t dx = dx_.decode(d, median3(x_diffs_), 0);
    store(&last[kX], addWrapping(load<std::int32_t>(&last[kX]), dx));
    std::uint32_t k = dx_.k();
    const std::int32_t dy = dy_.decode(d, median3(y_diffs_), k < 19 ? k : 19);
    store(&last[kY], addWrapping(load<std::int32_t>(&last[kY]), dy));
    k = (k + dy_.k()) / 2;
    store(&last[kZ], z_.decode(d, load<std::int32_t>(&last[kZ]), k < 19 ? k : 19));
    const std::uint32_t changed = d.decodeSymbol(changed_);
    if (changed & 32) {
      store<std::uint16_t>(&last[kIntensity], static_cast<std::uint16_t>(intensity_.decode(
                                                  d, load<std::uint16_t>(&last[kIntensity]), 0)));
    }
    if (changed & 16) last[kFlags] = flags_.decode(d, last[kFlags]);
    if (changed & 8) last[kClass] = classes_.decode(d, last[kClass]);
    if (changed & 4) {
      last[kScanAngle] = static_cast<std::uint8_t>(scan_angle_.decode(d, last[kScanAngle], k < 3));
    }
    if (changed & 2) last[kUserData] = user_data_.decode(d, last[kUserData]);
    if (changed & 1) {
      store<std::uint16_t>(&last[kSourceId], static_cast<std::uint16_t>(source_id_.decode(
                                                 d, load<std::uint16_t>(&last[kSourceId]), 0)));
    }
    x_diffs_[next_] = dx;
    y_diffs_[next_] = dy;
    next_ = next_ == 2 ? 0 : next_ + 1;
    std::memcpy(item, last, kPoint10Bytes);
    shared_ = d;
  }

 private:
  static std::int32_t median3(const std::array<std::int32_t, 3>& v) {
    if (v[0] < v[1]) return v[1] < v[2] ? v[1] : v[0] < v[2] ? v[2] : v[0];
    return v[0] < v[2] ? v[0] : v[1] < v[2] ? v[2] : v[1];
  }

  ArithmeticDecoder& shared_;  // the chunk's decoder, copied in and out by decode()
  std::array<std::uint8_t, kPoint10Bytes> last_{};
  std::array<std::int32_t, 3> x_diffs_{}, y_diffs_{};
  std::size_t next_ = 0;
  IntegerModels dx_{32, 1}, dy_{32, 20}, z_{32, 20}, intensity_{16, 1}, scan_angle_{8, 2},
      source_id_{16, 1};
  SymbolModel changed_{64};
  ByteModels flags_, classes_, user_data_;
};

// GPSTIME11 version 2: up to four interleaved time sequences (flight lines mixed in one file), each
// predicted by a multiple of its last difference.
class GpsTime11V2 final : public ItemDecoder {
 public:
  explicit GpsTime11V2(ArithmeticDecoder& decoder) : shared_(decoder) {}

  void start(const std::uint8_t* first) override {
    last_ = next_ = 0;
    diff_ = {};
    extreme_ = {};
    multi_.reset();
    zero_diff_.reset();
    time_.reset();
    times_ = {load<std::uint64_t>(first), 0, 0, 0};
  }

  void decode(std::uint8_t* item) override {
    ArithmeticDecoder d = shared_;  // in registers for the point (codegen/laz_arithmetic.h)
    // A switch to another sequence re-reads with that sequence's state; an encoder switches at
    // most once per point, so a stream asking for more is corrupt (and must not loop forever).
    for (int switches = 0; switches < kMaxSwitches; ++switches) {
      if (decodeStep(d)) break;
    }
    store(item, times_[last_]);
    shared_ = d;
  }

 private:
  static constexpr std::int32_t kMulti = kGpsMulti;
  static constexpr std::int32_t kMultiMinus = kGpsMultiMinus;
  static constexpr std::uint32_t kMultiUnchanged = kGpsMultiUnchanged;
  static constexpr std::uint32_t kMultiCodeFull = kGpsMultiCodeFull;
  static constexpr std::uint32_t kMultiTotal = kGpsMultiTotal;
  static constexpr int kMaxSwitches = 4;

  // A difference of `multi` times the last one; repeated extremes replace the last difference.
  void addDiff(std::int32_t diff, bool extreme) {
    if (extreme && ++extreme_[last_] > 3) {
      diff_[last_] = diff;
      extreme_[last_] = 0;
    }
    times_[last_] += static_cast<std::uint64_t>(static_cast<std::int64_t>(diff));
  }

  // A whole new time in a new sequence: its high 32 bits predicted by the current one's.
  __attribute__((always_inline)) void fullTime(ArithmeticDecoder& d) {
    next_ = (next_ + 1) & 3;
    const auto high = static_cast<std::uint32_t>(
        time_.decode(d, static_cast<std::int32_t>(times_[last_] >> 32), 8));
    times_[next_] = (static_cast<std::uint64_t>(high) << 32) | d.readInt();
    last_ = next_;
    diff_[last_] = 0;
    extreme_[last_] = 0;
  }

  // One decoding step; false when the stream switched sequences and the point is still to come.
  __attribute__((always_inline)) bool decodeStep(ArithmeticDecoder& d) {
    std::int32_t& last_diff = diff_[last_];
    if (last_diff == 0) {
      const std::uint32_t multi = d.decodeSymbol(zero_diff_);
      if (multi == 1) {
        last_diff = time_.decode(d, 0, 0);
        times_[last_] += static_cast<std::uint64_t>(static_cast<std::int64_t>(last_diff));
        extreme_[last_] = 0;
      } else if (multi == 2) {
        fullTime(d);
      } else if (multi > 2) {
        last_ = (last_ + multi - 2) & 3;
        return false;
      }
      return true;
    }
    const std::uint32_t multi = d.decodeSymbol(multi_);
    if (multi == 1) {
      times_[last_] +=
          static_cast<std::uint64_t>(static_cast<std::int64_t>(time_.decode(d, last_diff, 1)));
      extreme_[last_] = 0;
    } else if (multi < kMultiUnchanged) {
      if (multi == 0) {
        addDiff(time_.decode(d, 0, 7), true);
      } else if (multi < static_cast<std::uint32_t>(kMulti)) {
        const std::int32_t prediction = mulWrapping(static_cast<std::int32_t>(multi), last_diff);
        addDiff(time_.decode(d, prediction, multi < 10 ? 2 : 3), false);
      } else if (multi == static_cast<std::uint32_t>(kMulti)) {
        addDiff(time_.decode(d, mulWrapping(kMulti, last_diff), 4), true);
      } else {
        const std::int32_t negative = kMulti - static_cast<std::int32_t>(multi);
        if (negative > kMultiMinus) {
          addDiff(time_.decode(d, mulWrapping(negative, last_diff), 5), false);
        } else {
          addDiff(time_.decode(d, mulWrapping(kMultiMinus, last_diff), 6), true);
        }
      }
    } else if (multi == kMultiCodeFull) {
      fullTime(d);
    } else if (multi > kMultiCodeFull) {
      last_ = (last_ + multi - kMultiCodeFull) & 3;
      return false;
    }
    return true;
  }

  ArithmeticDecoder& shared_;  // the chunk's decoder, copied in and out by decode()
  std::uint32_t last_ = 0;
  std::uint32_t next_ = 0;
  std::array<std::uint64_t, 4> times_{};
  std::array<std::int32_t, 4> diff_{};
  std::array<std::int32_t, 4> extreme_{};
  SymbolModel multi_{kMultiTotal};
  SymbolModel zero_diff_{6};
  IntegerModels time_{32, 9};
};

// GPSTIME11 version 1: one sequence.
class GpsTime11V1 final : public ItemDecoder {
 public:
  explicit GpsTime11V1(ArithmeticDecoder& decoder) : shared_(decoder) {}

  void start(const std::uint8_t* first) override {
    diff_ = 0;
    extreme_ = 0;
    multi_.reset();
    zero_diff_.reset();
    time_.reset();
    time_bits_ = load<std::uint64_t>(first);
  }

  void decode(std::uint8_t* item) override {
    ArithmeticDecoder d = shared_;  // in registers for the point (codegen/laz_arithmetic.h)
    if (diff_ == 0) {
      const std::uint32_t multi = d.decodeSymbol(zero_diff_);
      if (multi == 1) {
        diff_ = time_.decode(d, 0, 0);
        add(diff_);
      } else if (multi == 2) {
        readWhole(d);
      }
    } else {
      const std::uint32_t multi = d.decodeSymbol(multi_);
      if (multi < kMultiMax - 2) {
        std::int32_t diff;
        if (multi == 1) {
          diff = time_.decode(d, diff_, 1);
          diff_ = diff;
          extreme_ = 0;
        } else if (multi == 0) {
          diff = time_.decode(d, diff_ / 4, 2);
          noteExtreme(diff);
        } else {
          const std::uint32_t context = multi < 10 ? 3 : multi < 50 ? 4 : 5;
          diff = time_.decode(d, mulWrapping(static_cast<std::int32_t>(multi), diff_), context);
          if (multi == kMultiMax - 3) noteExtreme(diff);
        }
        add(diff);
      } else if (multi < kMultiMax - 1) {
        readWhole(d);
      }
    }
    store(item, time_bits_);
    shared_ = d;
  }

 private:
  static constexpr std::uint32_t kMultiMax = 512;

  void add(std::int32_t diff) { time_bits_ += static_cast<std::uint64_t>(std::int64_t{diff}); }
  void noteExtreme(std::int32_t diff) {
    if (++extreme_ > 3) {
      diff_ = diff;
      extreme_ = 0;
    }
  }
  __attribute__((always_inline)) void readWhole(ArithmeticDecoder& d) {
    const std::uint64_t low = d.readInt();
    time_bits_ = (std::uint64_t{d.readInt()} << 32) | low;
  }

  ArithmeticDecoder& shared_;  // the chunk's decoder, copied in and out by decode()
  std::uint64_t time_bits_ = 0;
  std::int32_t diff_ = 0;
  std::int32_t extreme_ = 0;
  SymbolModel multi_{kMultiMax};
  SymbolModel zero_diff_{3};
  IntegerModels time_{32, 6};
};

// RGB12 version 2: the colour predicted from the last point's (decodeRgb).
class Rgb12V2 final : public ItemDecoder {
 public:
  explicit Rgb12V2(ArithmeticDecoder& decoder) : shared_(decoder) {}

  void start(const std::uint8_t* first) override {
    models_.reset();
    std::memcpy(last_.data(), first, 6);
  }

  void decode(std::uint8_t* item) override {
    ArithmeticDecoder d = shared_;  // in registers for the point (codegen/laz_arithmetic.h)
    decodeRgb(d, models_, last_.data(), last_.data());
    std::memcpy(item, last_.data(), 6);
    shared_ = d;
  }

 private:
  ArithmeticDecoder& shared_;  // the chunk's decoder, copied in and out by decode()
  std::array<std::uint8_t, 6> last_{};
  RgbModels models_;
};

// RGB12 version 1: each changed byte through one integer compressor, a context per byte.
class Rgb12V1 final : public ItemDecoder {
 public:
  explicit Rgb12V1(ArithmeticDecoder& decoder) : shared_(decoder) {}

  void start(const std::uint8_t* first) override {
    used_.reset();
    bytes_.reset();
    for (std::size_t c = 0; c < 3; ++c) last_[c] = load<std::uint16_t>(first + 2 * c);
  }

  void decode(std::uint8_t* item) override {
    ArithmeticDecoder d = shared_;  // in registers for the point (codegen/laz_arithmetic.h)
    const std::uint32_t used = d.decodeSymbol(used_);
    for (std::uint32_t c = 0; c < 3; ++c) {
      const std::uint32_t low_bit = 1u << (2 * c);
      const std::uint32_t high_bit = low_bit << 1;
      std::uint32_t value =
          (used & low_bit)
              ? static_cast<std::uint32_t>(bytes_.decode(d, last_[c] & 0xff, 2 * c)) & 0xffffu
              : last_[c] & 0xffu;
      value |=
          (used & high_bit)
              ? (static_cast<std::uint32_t>(bytes_.decode(d, last_[c] >> 8, 2 * c + 1)) & 0xffffu)
                    << 8
              : last_[c] & 0xff00u;
      last_[c] = static_cast<std::uint16_t>(value);
      store(item + 2 * c, last_[c]);
    }
    shared_ = d;
  }

 private:
  ArithmeticDecoder& shared_;  // the chunk's decoder, copied in and out by decode()
  std::array<std::uint16_t, 3> last_{};
  SymbolModel used_{64};
  IntegerModels bytes_{8, 6};
};

// WAVEPACKET13 version 1: the packet predicted from the last point's (decodeWavePacket).
class WavePacket13V1 final : public ItemDecoder {
 public:
  explicit WavePacket13V1(ArithmeticDecoder& decoder) : shared_(decoder) {}

  void start(const std::uint8_t* first) override {
    models_.reset();
    std::memcpy(last_.data(), first, last_.size());
  }

  void decode(std::uint8_t* item) override {
    ArithmeticDecoder d = shared_;  // in registers for the point (codegen/laz_arithmetic.h)
    decodeWavePacket(d, models_, last_.data(), last_.data());
    std::memcpy(item, last_.data(), last_.size());
    shared_ = d;
  }

 private:
  ArithmeticDecoder& shared_;  // the chunk's decoder, copied in and out by decode()
  std::array<std::uint8_t, kWavePacketBytes> last_{};
  WavePacketModels models_;
};

// BYTE (extra bytes) version 2: each byte's difference from the last point's, a model per byte.
class BytesV2 final : public ItemDecoder {
 public:
  BytesV2(ArithmeticDecoder& decoder, std::size_t count)
      : shared_(decoder), last_(count), models_(count, SymbolModel(256)) {}

  void start(const std::uint8_t* first) override {
    for (auto& model : models_) model.reset();
    std::memcpy(last_.data(), first, last_.size());
  }

  void decode(std::uint8_t* item) override {
    ArithmeticDecoder d = shared_;  // in registers for the point (codegen/laz_arithmetic.h)
    for (std::size_t i = 0; i < last_.size(); ++i) {
      last_[i] = foldByte(last_[i] + static_cast<std::int32_t>(d.decodeSymbol(models_[i])));
    }
    std::memcpy(item, last_.data(), last_.size());
    shared_ = d;
  }

 private:
  ArithmeticDecoder& shared_;  // the chunk's decoder, copied in and out by decode()
  std::vector<std::uint8_t> last_;
  std::vector<SymbolModel> models_;
};

// BYTE version 1: each byte through one integer compressor, a context per byte.
class BytesV1 final : public ItemDecoder {
 public:
  BytesV1(ArithmeticDecoder& decoder, std::size_t count)
      : shared_(decoder), last_(count), bytes_(8, static_cast<std::uint32_t>(count)) {}

  void start(const std::uint8_t* first) override {
    bytes_.reset();
    std::memcpy(last_.data(), first, last_.size());
  }

  void decode(std::uint8_t* item) override {
    ArithmeticDecoder d = shared_;  // in registers for the point (codegen/laz_arithmetic.h)
    for (std::size_t i = 0; i < last_.size(); ++i) {
      last_[i] =
          static_cast<std::uint8_t>(bytes_.decode(d, last_[i], static_cast<std::uint32_t>(i)));
    }
    std::memcpy(item, last_.data(), last_.size());
    shared_ = d;
  }

 private:
  ArithmeticDecoder& shared_;  // the chunk's decoder, copied in and out by decode()
  std::vector<std::uint8_t> last_;
  IntegerModels bytes_;
};

}  // namespace

std::string itemName(const Item& item) {
  std::string name;
  switch (item.type) {
    case ItemType::kByte:
      name = "BYTE";
      break;
    case ItemType::kPoint10:
      name = "POINT10";
      break;
    case ItemType::kGpsTime11:
      name = "GPSTIME11";
      break;
    case ItemType::kRgb12:
      name = "RGB12";
      break;
    case ItemType::kWavePacket13:
      name = "WAVEPACKET13";
      break;
    case ItemType::kPoint14:
      name = "POINT14";
      break;
    case ItemType::kRgb14:
      name = "RGB14";
      break;
    case ItemType::kRgbNir14:
      name = "RGBNIR14";
      break;
    case ItemType::kWavePacket14:
      name = "WAVEPACKET14";
      break;
    case ItemType::kByte14:
      name = "BYTE14";
      break;
    default:
      name = "item type " + std::to_string(static_cast<unsigned>(item.type));
  }
  return name + " version " + std::to_string(item.version);
}

std::unique_ptr<ItemDecoder> pointwiseDecoder(const Item& item, ArithmeticDecoder& decoder) {
  const int v = item.version;
  switch (item.type) {
    case ItemType::kPoint10:
      if (v == 1) return std::make_unique<Point10V1>(decoder);
      if (v == 2) return std::make_unique<Point10V2>(decoder);
      break;
    case ItemType::kGpsTime11:
      if (v == 1) return std::make_unique<GpsTime11V1>(decoder);
      if (v == 2) return std::make_unique<GpsTime11V2>(decoder);
      break;
    case ItemType::kRgb12:
      if (v == 1) return std::make_unique<Rgb12V1>(decoder);
      if (v == 2) return std::make_unique<Rgb12V2>(decoder);
      break;
    case ItemType::kWavePacket13:
      if (v == 1) return std::make_unique<WavePacket13V1>(decoder);
      break;
    case ItemType::kByte:
      if (v == 1) return std::make_unique<BytesV1>(decoder, item.size);
      if (v == 2) return std::make_unique<BytesV2>(decoder, item.size);
      break;
    default:
      break;
  }
  return nullptr;
}

}  // namespace octopoint::laz
