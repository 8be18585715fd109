// The LAZ point-wise version 2 encoder (tests/support/laz_encoder.h): each item's encoder mirrors
// its decoder in codegen/laz_pointwise.cpp, choosing what the decoder will read.

#include "tests/support/laz_encoder.h"

#include <array>
#include <cstring>
#include <stdexcept>
#include <string>

#include "codegen/laz_arithmetic.h"
#include "codegen/laz_integer.h"
#include "codegen/laz_layered_shared.h"
#include "codegen/laz_pointwise.h"
#include "codegen/laz_predictors.h"

namespace octopoint::testing {
namespace {

using namespace octopoint::laz;

template <typename T>
void append(std::vector<std::uint8_t>& out, T value) {
  const std::size_t at = out.size();
  out.resize(at + sizeof value);
  std::memcpy(out.data() + at, &value, sizeof value);
}

std::int32_t difference(std::int32_t a, std::int32_t b) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(a) - static_cast<std::uint32_t>(b));
}

class Encoder {
 public:
  virtual ~Encoder() = default;
  virtual void start(const std::uint8_t* first) = 0;
  virtual void encode(ArithmeticEncoder& e, const std::uint8_t* item) = 0;
};

class ByteModels {
 public:
  void encode(ArithmeticEncoder& e, std::uint8_t context, std::uint8_t value) {
    std::unique_ptr<SymbolModel>& model = models_[context];
    if (!model) model = std::make_unique<SymbolModel>(256, false);
    e.encodeSymbol(*model, value);
  }

 private:
  std::array<std::unique_ptr<SymbolModel>, 256> models_;
};

class Point10 final : public Encoder {
 public:
  void start(const std::uint8_t* first) override {
    std::memcpy(last_.data(), first, kPoint10Bytes);
    last_intensity_ = {};
    last_height_ = {};
  }

  void encode(ArithmeticEncoder& e, const std::uint8_t* item) override {
    const std::uint8_t* last = last_.data();
    const std::uint32_t number = returnNumber(item[kFlags]);
    const std::uint32_t count = returnCount(item[kFlags]);
    const std::uint32_t m = kReturnContext[count][number];
    const std::uint32_t level = returnLevel(count, number);
    const auto intensity = load<std::uint16_t>(item + kIntensity);
    const std::uint32_t changed = (std::uint32_t{last[kFlags] != item[kFlags]} << 5) |
                                  (std::uint32_t{last_intensity_[m] != intensity} << 4) |
                                  (std::uint32_t{last[kClass] != item[kClass]} << 3) |
                                  (std::uint32_t{last[kScanAngle] != item[kScanAngle]} << 2) |
                                  (std::uint32_t{last[kUserData] != item[kUserData]} << 1) |
                                  std::uint32_t{load<std::uint16_t>(last + kSourceId) !=
                                                load<std::uint16_t>(item + kSourceId)};
    e.encodeSymbol(changed_, changed);
    if (changed & 32) flags_.encode(e, last[kFlags], item[kFlags]);
    if (changed & 16) {
      intensity_.encode(e, last_intensity_[m], intensity, m < 3 ? m : 3);
      last_intensity_[m] = intensity;
    }
    if (changed & 8) classes_.encode(e, last[kClass], item[kClass]);
    if (changed & 4) {
      e.encodeSymbol(scan_angle_[scanDirection(item[kFlags])],
                     foldByte(item[kScanAngle] - last[kScanAngle]));
    }
    if (changed & 2) user_data_.encode(e, last[kUserData], item[kUserData]);
    if (changed & 1) {
      source_id_.encode(e, load<std::uint16_t>(last + kSourceId),
                        load<std::uint16_t>(item + kSourceId), 0);
    }
    const std::uint32_t single = count == 1;
    const std::int32_t dx =
        difference(load<std::int32_t>(item + kX), load<std::int32_t>(last + kX));
    dx_.encode(e, x_median_[m].get(), dx, single);
    x_median_[m].add(dx);
    std::uint32_t k = dx_.k();
    const std::int32_t dy =
        difference(load<std::int32_t>(item + kY), load<std::int32_t>(last + kY));
    dy_.encode(e, y_median_[m].get(), dy, single + (k < 20 ? evenBelow(k) : 20));
    y_median_[m].add(dy);
    k = (dx_.k() + dy_.k()) / 2;
    const auto z = load<std::int32_t>(item + kZ);
    z_.encode(e, last_height_[level], z, single + (k < 18 ? evenBelow(k) : 18));
    last_height_[level] = z;
    std::memcpy(last_.data(), item, kPoint10Bytes);
  }

 private:
  std::array<std::uint8_t, kPoint10Bytes> last_{};
  std::array<Median5, 16> x_median_, y_median_;
  std::array<std::uint16_t, 16> last_intensity_{};
  std::array<std::int32_t, 8> last_height_{};
  SymbolModel changed_{64, false};
  IntegerModels intensity_{16, 4, false};
  std::array<SymbolModel, 2> scan_angle_{SymbolModel(256, false), SymbolModel(256, false)};
  IntegerModels source_id_{16, 1, false};
  ByteModels flags_, classes_, user_data_;
  IntegerModels dx_{32, 2, false}, dy_{32, 22, false}, z_{32, 20, false};
};

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

class GpsTime11 final : public Encoder {
 public:
  void start(const std::uint8_t* first) override { coder_.start(load<std::int64_t>(first)); }
  void encode(ArithmeticEncoder& e, const std::uint8_t* item) override {
    coder_.encode(e, load<std::int64_t>(item));
  }

 private:
  GpsTimeCoder coder_{false};
};

// The colour coded from the last (codegen/laz_pointwise.h decodeRgb is its inverse).
void encodeRgb(ArithmeticEncoder& e, RgbModels& models, const std::uint8_t* last,
               const std::uint8_t* item) {
  std::array<std::int32_t, 3> lo{}, hi{}, last_lo{}, last_hi{};
  for (std::size_t c = 0; c < 3; ++c) {
    const auto v = load<std::uint16_t>(item + 2 * c);
    const auto l = load<std::uint16_t>(last + 2 * c);
    lo[c] = v & 0xff;
    hi[c] = v >> 8;
    last_lo[c] = l & 0xff;
    last_hi[c] = l >> 8;
  }
  std::uint32_t used = 0;
  for (std::uint32_t c = 0; c < 3; ++c) {
    used |= std::uint32_t{lo[c] != last_lo[c]} << (2 * c);
    used |= std::uint32_t{hi[c] != last_hi[c]} << (2 * c + 1);
  }
  const bool colour = lo[0] != lo[1] || lo[0] != lo[2] || hi[0] != hi[1] || hi[0] != hi[2];
  used |= std::uint32_t{colour} << 6;
  e.encodeSymbol(models.used, used);
  std::int32_t diff_lo = 0;
  std::int32_t diff_hi = 0;
  if (used & 1) {
    diff_lo = lo[0] - last_lo[0];
    e.encodeSymbol(models.diff[0], foldByte(diff_lo));
  }
  if (used & 2) {
    diff_hi = hi[0] - last_hi[0];
    e.encodeSymbol(models.diff[1], foldByte(diff_hi));
  }
  if (!colour) return;
  if (used & 4) e.encodeSymbol(models.diff[2], foldByte(lo[1] - clampByte(diff_lo + last_lo[1])));
  if (used & 16) {
    diff_lo = (diff_lo + lo[1] - last_lo[1]) / 2;
    e.encodeSymbol(models.diff[4], foldByte(lo[2] - clampByte(diff_lo + last_lo[2])));
  }
  if (used & 8) e.encodeSymbol(models.diff[3], foldByte(hi[1] - clampByte(diff_hi + last_hi[1])));
  if (used & 32) {
    diff_hi = (diff_hi + hi[1] - last_hi[1]) / 2;
    e.encodeSymbol(models.diff[5], foldByte(hi[2] - clampByte(diff_hi + last_hi[2])));
  }
}

class Rgb12 final : public Encoder {
 public:
  void start(const std::uint8_t* first) override {
    models_.reset();
    std::memcpy(last_.data(), first, last_.size());
  }
  void encode(ArithmeticEncoder& e, const std::uint8_t* item) override {
    encodeRgb(e, models_, last_.data(), item);
    std::memcpy(last_.data(), item, last_.size());
  }

 private:
  std::array<std::uint8_t, 6> last_{};
  RgbModels models_;
};

class Bytes final : public Encoder {
 public:
  explicit Bytes(std::size_t count) : last_(count), models_(count, SymbolModel(256, false)) {}

  void start(const std::uint8_t* first) override { std::memcpy(last_.data(), first, last_.size()); }

  void encode(ArithmeticEncoder& e, const std::uint8_t* item) override {
    for (std::size_t i = 0; i < last_.size(); ++i)
      e.encodeSymbol(models_[i], foldByte(item[i] - last_[i]));
    std::memcpy(last_.data(), item, last_.size());
  }

 private:
  std::vector<std::uint8_t> last_;
  std::vector<SymbolModel> models_;
};

// One layer of a layered chunk: its own arithmetic code. It is written only when its field
// changed somewhere in the chunk (or always, for POINT14's first layer); else the decoder keeps
// the first point's value, which is then every point's.
class LayerOut {
 public:
  void start() {
    bytes_.clear();
    coder_.start();
    changed_ = false;
  }
  ArithmeticEncoder& coder() { return coder_; }
  void note(bool changed) { changed_ = changed_ || changed; }
  std::vector<std::uint8_t> finish(bool always = false) {
    if (!changed_ && !always) return {};
    coder_.finish();
    return bytes_;
  }

 private:
  std::vector<std::uint8_t> bytes_;
  ArithmeticEncoder coder_{bytes_};
  bool changed_ = false;
};

class LayeredEncoder {
 public:
  virtual ~LayeredEncoder() = default;
  virtual void start(const std::uint8_t* first, std::uint32_t channel) = 0;
  virtual void encode(const std::uint8_t* item, std::uint32_t channel) = 0;
  // Appends the item's layers, in order (empty ones included).
  virtual void finish(std::vector<std::vector<std::uint8_t>>& layers) = 0;
};

// A symbol model per context, made on first use.
class LazyModels {
 public:
  explicit LazyModels(std::uint32_t symbols) : symbols_(symbols) {}
  SymbolModel& operator[](std::size_t i) {
    std::unique_ptr<SymbolModel>& model = models_[i];
    if (!model) model = std::make_unique<SymbolModel>(symbols_, false);
    return *model;
  }

 private:
  std::uint32_t symbols_;
  std::array<std::unique_ptr<SymbolModel>, 64> models_;
};

struct Point14Context {
  bool used = false;
  bool gps_changed = false;
  std::array<std::uint8_t, kPoint14Bytes> last{};
  std::vector<SymbolModel> changed = std::vector<SymbolModel>(8, SymbolModel(128, false));
  SymbolModel channel{3, false};
  LazyModels return_count{16}, return_number{16};
  SymbolModel return_number_same_time{13, false};
  IntegerModels dx{32, 2, false}, dy{32, 22, false}, z{32, 20, false};
  std::array<Median5, 12> x_median, y_median;
  std::array<std::int32_t, 8> last_z{};
  LazyModels classes{256}, flags{64}, user_data{256};
  IntegerModels intensity{16, 4, false}, scan_angle{16, 2, false}, source_id{16, 1, false};
  std::array<std::uint16_t, 8> last_intensity{};
  GpsTimeCoder gps{true};

  // A fresh context from `item` (a chunk's first point, or the point before a channel's first).
  void reset(const std::uint8_t* item) {
    last_z.fill(load<std::int32_t>(item + kZ));
    last_intensity.fill(load<std::uint16_t>(item + kIntensity));
    gps.start(load<std::int64_t>(item + kGpsTime14));
    std::memcpy(last.data(), item, kPoint14Bytes);
    gps_changed = false;
    used = true;
  }
};

// POINT14 version 3 (the inverse of codegen/laz_layered.cpp's Point14V3).
class Point14Layered final : public LayeredEncoder {
 public:
  void start(const std::uint8_t* first, std::uint32_t channel) override {
    for (auto& layer : layers_) layer.start();
    for (auto& context : contexts_) context.reset();
    current_ = channel;
    context(current_).reset(first);
  }

  void encode(const std::uint8_t* item, std::uint32_t channel) override {
    Point14Context* c = &context(current_);
    ArithmeticEncoder& xy = layers_[0].coder();
    const std::uint32_t prev_number = c->last[kReturns] & 15u;
    const std::uint32_t prev_count = c->last[kReturns] >> 4;
    const std::uint32_t last_return = (prev_number == 1 ? 1u : 0u) |
                                      (prev_number >= prev_count ? 2u : 0u) |
                                      (c->gps_changed ? 4u : 0u);
    SymbolModel& changed_model = c->changed[last_return];
    SymbolModel& channel_model = c->channel;
    const std::uint32_t previous = current_;
    if (channel != current_) {
      if (!contexts_[channel] || !contexts_[channel]->used) context(channel).reset(c->last.data());
      current_ = channel;
      c = &context(channel);
      c->last[kFlags14] = static_cast<std::uint8_t>((c->last[kFlags14] & 0xcf) | (channel << 4));
    }
    std::uint8_t* last = c->last.data();
    const std::uint32_t last_number = last[kReturns] & 15u;
    const std::uint32_t last_count = last[kReturns] >> 4;
    const std::uint32_t number = item[kReturns] & 15u;
    const std::uint32_t count = item[kReturns] >> 4;
    const bool source_changed =
        load<std::uint16_t>(item + kSourceId14) != load<std::uint16_t>(last + kSourceId14);
    const bool gps_changed =
        load<std::uint64_t>(item + kGpsTime14) != load<std::uint64_t>(last + kGpsTime14);
    const bool scan_angle_changed =
        load<std::uint16_t>(item + kScanAngle14) != load<std::uint16_t>(last + kScanAngle14);
    const std::uint32_t number_code = number == last_number                  ? 0u
                                      : number == ((last_number + 1) & 15u)  ? 1u
                                      : number == ((last_number + 15) & 15u) ? 2u
                                                                             : 3u;
    const std::uint32_t changed = number_code | (count != last_count ? 4u : 0u) |
                                  (scan_angle_changed ? 8u : 0u) | (gps_changed ? 16u : 0u) |
                                  (source_changed ? 32u : 0u) | (channel != previous ? 64u : 0u);
    xy.encodeSymbol(changed_model, changed);
    if (changed & 64) xy.encodeSymbol(channel_model, (channel - previous - 1) & 3u);
    if (changed & 4) xy.encodeSymbol(c->return_count[last_count], count);
    if (number_code == 3) {
      if (gps_changed) {
        xy.encodeSymbol(c->return_number[last_number], number);
      } else {
        xy.encodeSymbol(c->return_number_same_time, (number - last_number - 2) & 15u);
      }
    }
    const std::uint32_t m = (std::uint32_t{kReturnMap6[count][number]} << 1) | gps_changed;
    const std::uint32_t level = returnLevel8(count, number);
    const std::uint32_t position = (number == 1 ? 2u : 0u) | (number >= count ? 1u : 0u);
    const std::uint32_t single = count == 1;

    const std::int32_t dx =
        difference(load<std::int32_t>(item + kX), load<std::int32_t>(last + kX));
    c->dx.encode(xy, c->x_median[m].get(), dx, single);
    c->x_median[m].add(dx);
    std::uint32_t k = c->dx.k();
    const std::int32_t dy =
        difference(load<std::int32_t>(item + kY), load<std::int32_t>(last + kY));
    c->dy.encode(xy, c->y_median[m].get(), dy, single + (k < 20 ? evenBelow(k) : 20));
    c->y_median[m].add(dy);

    k = (c->dx.k() + c->dy.k()) / 2;
    const auto z = load<std::int32_t>(item + kZ);
    c->z.encode(layers_[1].coder(), c->last_z[level], z, single + (k < 18 ? evenBelow(k) : 18));
    c->last_z[level] = z;
    layers_[1].note(z != load<std::int32_t>(last + kZ));

    const std::uint32_t class_context = ((last[kClass14] & 0x1fu) << 1) | (position == 3 ? 1u : 0u);
    layers_[2].coder().encodeSymbol(c->classes[class_context], item[kClass14]);
    layers_[2].note(item[kClass14] != last[kClass14]);

    const auto flags = [](std::uint8_t byte) {
      return (byte & 15u) | (((byte >> 6) & 1u) << 4) | ((byte >> 7) << 5);
    };
    layers_[3].coder().encodeSymbol(c->flags[flags(last[kFlags14])], flags(item[kFlags14]));
    layers_[3].note(flags(item[kFlags14]) != flags(last[kFlags14]));

    const auto intensity = load<std::uint16_t>(item + kIntensity);
    const std::uint32_t intensity_context = (position << 1) | gps_changed;
    c->intensity.encode(layers_[4].coder(), c->last_intensity[intensity_context], intensity,
                        position);
    c->last_intensity[intensity_context] = intensity;
    layers_[4].note(intensity != load<std::uint16_t>(last + kIntensity));

    if (scan_angle_changed) {
      c->scan_angle.encode(layers_[5].coder(), load<std::int16_t>(last + kScanAngle14),
                           load<std::int16_t>(item + kScanAngle14), gps_changed);
      layers_[5].note(true);
    }
    layers_[6].coder().encodeSymbol(c->user_data[last[kUserData14] / 4], item[kUserData14]);
    layers_[6].note(item[kUserData14] != last[kUserData14]);
    if (source_changed) {
      c->source_id.encode(layers_[7].coder(), load<std::uint16_t>(last + kSourceId14),
                          load<std::uint16_t>(item + kSourceId14), 0);
      layers_[7].note(true);
    }
    if (gps_changed) {
      c->gps.encode(layers_[8].coder(), load<std::int64_t>(item + kGpsTime14));
      layers_[8].note(true);
    }
    std::memcpy(last, item, kPoint14Bytes);
    c->gps_changed = gps_changed;
  }

  void finish(std::vector<std::vector<std::uint8_t>>& layers) override {
    for (std::size_t i = 0; i < layers_.size(); ++i) layers.push_back(layers_[i].finish(i == 0));
  }

 private:
  Point14Context& context(std::uint32_t channel) {
    if (!contexts_[channel]) contexts_[channel] = std::make_unique<Point14Context>();
    return *contexts_[channel];
  }

  std::array<LayerOut, 9> layers_;
  std::array<std::unique_ptr<Point14Context>, 4> contexts_;
  std::uint32_t current_ = 0;
};

// RGB14 and RGBNIR14 version 3.
class ColourLayered final : public LayeredEncoder {
 public:
  explicit ColourLayered(bool nir) : nir_(nir) {}
  void start(const std::uint8_t* first, std::uint32_t channel) override {
    rgb_.start();
    nir_layer_.start();
    std::array<std::uint8_t, 8> item{};
    std::memcpy(item.data(), first, nir_ ? 8 : 6);
    follower_.start(item.data(), channel);
  }
  void encode(const std::uint8_t* item, std::uint32_t channel) override {
    auto [c, last] = follower_.follow(channel);
    encodeRgb(rgb_.coder(), c->rgb, last, item);
    rgb_.note(std::memcmp(last, item, 6) != 0);
    std::memcpy(last, item, 6);
    if (!nir_) return;
    std::uint32_t used = 0;
    for (std::size_t byte = 0; byte < 2; ++byte)
      used |= std::uint32_t{item[6 + byte] != last[6 + byte]} << byte;
    ArithmeticEncoder& e = nir_layer_.coder();
    e.encodeSymbol(c->nir_used, used);
    for (std::size_t byte = 0; byte < 2; ++byte) {
      if (used & (1u << byte))
        e.encodeSymbol(c->nir_diff[byte], foldByte(item[6 + byte] - last[6 + byte]));
    }
    nir_layer_.note(used != 0);
    std::memcpy(last + 6, item + 6, 2);
  }
  void finish(std::vector<std::vector<std::uint8_t>>& layers) override {
    layers.push_back(rgb_.finish());
    if (nir_) layers.push_back(nir_layer_.finish());
  }

 private:
  bool nir_;
  LayerOut rgb_, nir_layer_;
  ChannelFollower<RgbContext> follower_;
};

// BYTE14 version 3: a layer per byte.
class BytesLayered final : public LayeredEncoder {
 public:
  explicit BytesLayered(std::size_t count) : count_(count) {
    for (std::size_t i = 0; i < count; ++i) layers_.push_back(std::make_unique<LayerOut>());
  }
  void start(const std::uint8_t* first, std::uint32_t channel) override {
    for (auto& layer : layers_) layer->start();
    for (auto& context : contexts_) context.used = false;
    current_ = channel;
    reset(current_, first);
  }
  void encode(const std::uint8_t* item, std::uint32_t channel) override {
    std::uint8_t* last = contexts_[current_].last.data();
    if (channel != current_) {
      current_ = channel;
      if (!contexts_[current_].used) {
        reset(current_, last);
        last = contexts_[current_].last.data();
      }
    }
    BytesContext& c = contexts_[current_];
    for (std::size_t i = 0; i < count_; ++i) {
      layers_[i]->coder().encodeSymbol(c.models[i], foldByte(item[i] - last[i]));
      layers_[i]->note(item[i] != last[i]);
      last[i] = item[i];
    }
  }
  void finish(std::vector<std::vector<std::uint8_t>>& layers) override {
    for (auto& layer : layers_) layers.push_back(layer->finish());
  }

 private:
  void reset(std::uint32_t channel, const std::uint8_t* item) {
    contexts_[channel].reset(item, count_);
  }

  std::size_t count_;
  std::vector<std::unique_ptr<LayerOut>> layers_;
  std::array<BytesContext, 4> contexts_;
  std::uint32_t current_ = 0;
};

struct ItemSpec {
  std::uint16_t type;
  std::uint16_t size;
};

std::vector<ItemSpec> itemsOf(int format, int extra_bytes) {
  if (format < 0 || (format > 3 && format < 6) || format > 8) {
    throw std::runtime_error("LAZ is written for point formats 0 to 3 and 6 to 8, not " +
                             std::to_string(format));
  }
  if (format >= 6) {                            // the layered items
    std::vector<ItemSpec> items = {{10, 30}};   // POINT14
    if (format == 7) items.push_back({11, 6});  // RGB14
    if (format == 8) items.push_back({12, 8});  // RGBNIR14
    if (extra_bytes > 0) items.push_back({14, static_cast<std::uint16_t>(extra_bytes)});  // BYTE14
    return items;
  }
  std::vector<ItemSpec> items = {{6, 20}};                                             // POINT10
  if (format == 1 || format == 3) items.push_back({7, 8});                             // GPSTIME11
  if (format >= 2) items.push_back({8, 6});                                            // RGB12
  if (extra_bytes > 0) items.push_back({0, static_cast<std::uint16_t>(extra_bytes)});  // BYTE
  return items;
}

}  // namespace

struct LazChunkEncoder::State {
  std::vector<ItemSpec> items;
  std::vector<std::unique_ptr<Encoder>> encoders;
  std::vector<std::unique_ptr<LayeredEncoder>> layered_encoders;  // formats 6 to 8
  std::uint32_t last_channel = 0;  // the last point's scanner channel (layered)
  std::size_t record_bytes = 0;
  std::vector<std::uint8_t> bytes;
  ArithmeticEncoder coder{bytes};
  std::uint64_t points = 0;
  int format = 0;
  int extra_bytes = 0;

  bool layered() const { return format >= 6; }

  // Fresh models for every chunk: the decoder starts each chunk from scratch.
  void makeEncoders() {
    encoders.clear();
    layered_encoders.clear();
    if (layered()) {
      for (const ItemSpec& item : items) {
        if (item.type == 10) {
          layered_encoders.push_back(std::make_unique<Point14Layered>());
        } else if (item.type == 11 || item.type == 12) {
          layered_encoders.push_back(std::make_unique<ColourLayered>(item.type == 12));
        } else {
          layered_encoders.push_back(std::make_unique<BytesLayered>(item.size));
        }
      }
      return;
    }
    for (const ItemSpec& item : items) {
      switch (item.type) {
        case 6:
          encoders.push_back(std::make_unique<Point10>());
          break;
        case 7:
          encoders.push_back(std::make_unique<GpsTime11>());
          break;
        case 8:
          encoders.push_back(std::make_unique<Rgb12>());
          break;
        default:
          encoders.push_back(std::make_unique<Bytes>(item.size));
          break;
      }
    }
  }
};

LazChunkEncoder::LazChunkEncoder(int format, int extra_bytes) : state_(std::make_unique<State>()) {
  state_->items = itemsOf(format, extra_bytes);
  state_->format = format;
  state_->extra_bytes = extra_bytes;
  for (const ItemSpec& item : state_->items) state_->record_bytes += item.size;
}

LazChunkEncoder::~LazChunkEncoder() = default;

std::uint64_t LazChunkEncoder::points() const { return state_->points; }

void LazChunkEncoder::add(const std::uint8_t* record) {
  State& s = *state_;
  if (s.layered()) {
    const std::uint32_t channel = (record[15] >> 4) & 3u;  // POINT14's scanner channel
    if (s.points == 0) {
      s.bytes.assign(record, record + s.record_bytes);  // the first point raw
      s.makeEncoders();
    }
    // The items after POINT14 are told the channel on a change of channel and 0 on the other
    // points, as the decoders are (codegen/laz_layered.h).
    const std::uint32_t context = s.points == 0 || channel != s.last_channel ? channel : 0;
    std::size_t at = 0;
    for (std::size_t i = 0; i < s.items.size(); ++i) {
      if (s.points == 0) {
        s.layered_encoders[i]->start(record + at, channel);
      } else {
        s.layered_encoders[i]->encode(record + at, i == 0 ? channel : context);
      }
      at += s.items[i].size;
    }
    s.last_channel = channel;
    ++s.points;
    return;
  }
  if (s.points == 0) {  // the first point raw, then the arithmetic code starts
    s.bytes.assign(record, record + s.record_bytes);
    s.makeEncoders();
    std::size_t at = 0;
    for (std::size_t i = 0; i < s.items.size(); ++i) {
      s.encoders[i]->start(record + at);
      at += s.items[i].size;
    }
    s.coder.start();
  } else {
    std::size_t at = 0;
    for (std::size_t i = 0; i < s.items.size(); ++i) {
      s.encoders[i]->encode(s.coder, record + at);
      at += s.items[i].size;
    }
  }
  ++s.points;
}

std::vector<std::uint8_t> LazChunkEncoder::finishChunk() {
  State& s = *state_;
  if (s.layered() && s.points > 0) {
    // the first point raw, the point count, every layer's size, the layers
    std::vector<std::vector<std::uint8_t>> layers;
    for (auto& encoder : s.layered_encoders) encoder->finish(layers);
    append<std::uint32_t>(s.bytes, static_cast<std::uint32_t>(s.points));
    for (const auto& layer : layers)
      append<std::uint32_t>(s.bytes, static_cast<std::uint32_t>(layer.size()));
    for (const auto& layer : layers) s.bytes.insert(s.bytes.end(), layer.begin(), layer.end());
  } else if (s.points > 0) {
    s.coder.finish();
  }
  s.points = 0;
  std::vector<std::uint8_t> out;
  out.swap(s.bytes);
  return out;
}

std::vector<std::uint8_t> LazChunkEncoder::vlrPayload(std::uint32_t chunk_size) const {
  std::vector<std::uint8_t> out;
  append<std::uint16_t>(out, state_->layered() ? 3 : 2);  // layered or point-wise chunked
  append<std::uint16_t>(out, 0);                          // coder: arithmetic
  out.push_back(3);  // LASzip version 3.4, revision 3, as LASzip writes today
  out.push_back(4);
  append<std::uint16_t>(out, 3);
  append<std::uint32_t>(out, 0);  // options
  append<std::uint32_t>(out, chunk_size);
  append<std::int64_t>(out, -1);  // no special EVLRs
  append<std::int64_t>(out, -1);
  append<std::uint16_t>(out, static_cast<std::uint16_t>(state_->items.size()));
  for (const ItemSpec& item : state_->items) {
    append<std::uint16_t>(out, item.type);
    append<std::uint16_t>(out, item.size);
    append<std::uint16_t>(out, state_->layered() ? 3 : 2);  // item version
  }
  return out;
}

std::vector<std::uint8_t> lazChunkTable(const std::vector<std::uint64_t>& chunk_points,
                                        const std::vector<std::uint64_t>& chunk_bytes,
                                        bool variable) {
  std::vector<std::uint8_t> out;
  append<std::uint32_t>(out, 0);  // version
  append<std::uint32_t>(out, static_cast<std::uint32_t>(chunk_bytes.size()));
  ArithmeticEncoder coder(out);
  coder.start();
  IntegerModels sizes(32, 2, false);
  sizes.reset();
  for (std::size_t i = 0; i < chunk_bytes.size(); ++i) {
    if (variable) {
      sizes.encode(coder, i ? static_cast<std::int32_t>(chunk_points[i - 1]) : 0,
                   static_cast<std::int32_t>(chunk_points[i]), 0);
    }
    sizes.encode(coder, i ? static_cast<std::int32_t>(chunk_bytes[i - 1]) : 0,
                 static_cast<std::int32_t>(chunk_bytes[i]), 1);
  }
  coder.finish();
  return out;
}

}  // namespace octopoint::testing
