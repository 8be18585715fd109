// The LAZ point-wise version 2 encoder (tests/support/laz_encoder.h): each item's encoder mirrors
// its decoder in codegen/laz_pointwise.cpp, choosing what the decoder will read.

#include "tests/support/laz_encoder.h"

#include <array>
#include <cstring>
#include <stdexcept>
#include <string>

#include "codegen/laz_arithmetic.h"
#include "codegen/laz_integer.h"
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

class GpsTime11 final : public Encoder {
 public:
  void start(const std::uint8_t* first) override {
    last_ = next_ = 0;
    diff_ = {};
    extreme_ = {};
    times_ = {load<std::int64_t>(first), 0, 0, 0};
  }

  void encode(ArithmeticEncoder& e, const std::uint8_t* item) override {
    const auto time = load<std::int64_t>(item);
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
      if (diff64 == 0) {
        e.encodeSymbol(zero_diff_, 0);
        return true;
      }
      if (fits32(diff64)) {
        e.encodeSymbol(zero_diff_, 1);
        time_.encode(e, 0, diff, 0);
        diff_[last_] = diff;
        extreme_[last_] = 0;
      } else if (const std::uint32_t other = otherSequence(time)) {
        e.encodeSymbol(zero_diff_, other + 2);
        last_ = (last_ + other) & 3;
        return false;
      } else {
        e.encodeSymbol(zero_diff_, 2);
        startSequence(e, time);
      }
      times_[last_] = time;
      return true;
    }
    if (diff64 == 0) {
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
      e.encodeSymbol(multi_, kGpsMultiCodeFull + other);
      last_ = (last_ + other) & 3;
      return false;
    } else {
      e.encodeSymbol(multi_, kGpsMultiCodeFull);
      startSequence(e, time);
    }
    times_[last_] = time;
    return true;
  }

  std::uint32_t last_ = 0;
  std::uint32_t next_ = 0;
  std::array<std::int64_t, 4> times_{};
  std::array<std::int32_t, 4> diff_{};
  std::array<std::int32_t, 4> extreme_{};
  SymbolModel multi_{kGpsMultiTotal, false};
  SymbolModel zero_diff_{6, false};
  IntegerModels time_{32, 9, false};
};

class Rgb12 final : public Encoder {
 public:
  void start(const std::uint8_t* first) override {
    for (std::size_t c = 0; c < 3; ++c) last_[c] = load<std::uint16_t>(first + 2 * c);
  }

  void encode(ArithmeticEncoder& e, const std::uint8_t* item) override {
    std::array<std::int32_t, 3> lo{}, hi{}, last_lo{}, last_hi{};
    for (std::size_t c = 0; c < 3; ++c) {
      const auto v = load<std::uint16_t>(item + 2 * c);
      lo[c] = v & 0xff;
      hi[c] = v >> 8;
      last_lo[c] = last_[c] & 0xff;
      last_hi[c] = last_[c] >> 8;
    }
    std::uint32_t used = 0;
    for (std::uint32_t c = 0; c < 3; ++c) {
      used |= std::uint32_t{lo[c] != last_lo[c]} << (2 * c);
      used |= std::uint32_t{hi[c] != last_hi[c]} << (2 * c + 1);
    }
    const bool colour = lo[0] != lo[1] || lo[0] != lo[2] || hi[0] != hi[1] || hi[0] != hi[2];
    used |= std::uint32_t{colour} << 6;
    e.encodeSymbol(used_, used);
    std::int32_t diff_lo = 0;
    std::int32_t diff_hi = 0;
    if (used & 1) {
      diff_lo = lo[0] - last_lo[0];
      e.encodeSymbol(diff_[0], foldByte(diff_lo));
    }
    if (used & 2) {
      diff_hi = hi[0] - last_hi[0];
      e.encodeSymbol(diff_[1], foldByte(diff_hi));
    }
    if (colour) {
      if (used & 4) e.encodeSymbol(diff_[2], foldByte(lo[1] - clampByte(diff_lo + last_lo[1])));
      if (used & 16) {
        diff_lo = (diff_lo + lo[1] - last_lo[1]) / 2;
        e.encodeSymbol(diff_[4], foldByte(lo[2] - clampByte(diff_lo + last_lo[2])));
      }
      if (used & 8) e.encodeSymbol(diff_[3], foldByte(hi[1] - clampByte(diff_hi + last_hi[1])));
      if (used & 32) {
        diff_hi = (diff_hi + hi[1] - last_hi[1]) / 2;
        e.encodeSymbol(diff_[5], foldByte(hi[2] - clampByte(diff_hi + last_hi[2])));
      }
    }
    for (std::size_t c = 0; c < 3; ++c) last_[c] = load<std::uint16_t>(item + 2 * c);
  }

 private:
  std::array<std::uint16_t, 3> last_{};
  SymbolModel used_{128, false};
  std::array<SymbolModel, 6> diff_{SymbolModel(256, false), SymbolModel(256, false),
                                   SymbolModel(256, false), SymbolModel(256, false),
                                   SymbolModel(256, false), SymbolModel(256, false)};
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

struct ItemSpec {
  std::uint16_t type;
  std::uint16_t size;
};

std::vector<ItemSpec> itemsOf(int format, int extra_bytes) {
  if (format < 0 || format > 3) {
    throw std::runtime_error("LAZ is written for point formats 0 to 3, not " +
                             std::to_string(format));
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
  std::size_t record_bytes = 0;
  std::vector<std::uint8_t> bytes;
  ArithmeticEncoder coder{bytes};
  std::uint64_t points = 0;
  int format = 0;
  int extra_bytes = 0;

  // Fresh models for every chunk: the decoder starts each chunk from scratch.
  void makeEncoders() {
    encoders.clear();
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
  if (s.points > 0) s.coder.finish();
  s.points = 0;
  std::vector<std::uint8_t> out;
  out.swap(s.bytes);
  return out;
}

std::vector<std::uint8_t> LazChunkEncoder::vlrPayload(std::uint32_t chunk_size) const {
  std::vector<std::uint8_t> out;
  append<std::uint16_t>(out, 2);  // compressor: point-wise chunked
  append<std::uint16_t>(out, 0);  // coder: arithmetic
  out.push_back(3);               // LASzip version 3.4, revision 3, as LASzip writes today
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
    append<std::uint16_t>(out, 2);  // version 2
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
