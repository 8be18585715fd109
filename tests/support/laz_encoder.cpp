// The LAZ encoder (tests/support/laz_encoder.h): chunks, and point-wise items version 2 here (the
// layered ones in tests/support/laz_layered_encoder.cpp); each item's encoder mirrors its decoder
// in codegen/laz_pointwise.cpp, choosing what the decoder will read.

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
#include "tests/support/laz_layered_encoder.h"
#include "tests/support/laz_shared_encoders.h"

namespace octopoint::testing {
namespace {

using namespace octopoint::laz;

template <typename T>
void append(std::vector<std::uint8_t>& out, T value) {
  const std::size_t at = out.size();
  out.resize(at + sizeof value);
  std::memcpy(out.data() + at, &value, sizeof value);
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
  void start(const std::uint8_t* first) override { coder_.start(load<std::int64_t>(first)); }
  void encode(ArithmeticEncoder& e, const std::uint8_t* item) override {
    coder_.encode(e, load<std::int64_t>(item));
  }

 private:
  GpsTimeCoder coder_{false};
};

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
          layered_encoders.push_back(makePoint14Layered());
        } else if (item.type == 11 || item.type == 12) {
          layered_encoders.push_back(makeColourLayered(item.type == 12));
        } else {
          layered_encoders.push_back(makeBytesLayered(item.size));
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
