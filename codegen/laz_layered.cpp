// The layered LAZ item decoders (codegen/laz_layered.h), written from the LAZ specification's
// description of LASzip's version 3 items and checked against files LASzip wrote. Coordinates and
// times wrap in uint32/uint64 as the format's two's complement values do.

#include "codegen/laz_layered.h"

#include <array>
#include <cstring>
#include <utility>
#include <vector>

#include "codegen/laz_integer.h"
#include "codegen/laz_layered_shared.h"
#include "codegen/laz_predictors.h"

namespace octopoint::laz {
namespace {

using prepare::RecordField;
using prepare::RecordFields;

// One layer of a chunk: its bytes and the arithmetic decoder reading them. An empty layer is not
// started: its field keeps the value of the chunk's first point. Neither is a layer the caller does
// not want (codegen/record_fields.h): its bytes are stepped over, its field left as it is.
class Layer {
 public:
  void start(std::span<const std::uint8_t> bytes, bool wanted) {
    if (!wanted) bytes = {};
    input_.assign(bytes);
    present_ = !bytes.empty();
    if (present_) {
      decoder_.attach(input_);
      decoder_.start();
    }
  }
  bool present() const { return present_; }
  ArithmeticDecoder& decoder() { return decoder_; }
  bool overrun() const { return present_ && decoder_.overrun() > 0; }
  bool exact() const {
    return !present_ || (decoder_.overrun() == 0 && decoder_.unread() == 0 && !decoder_.failed());
  }

 private:
  MemoryInput input_{{}};
  ArithmeticDecoder decoder_;
  bool present_ = false;
};

template <std::size_t N>
int firstInexact(const std::array<Layer, N>& layers) {
  for (std::size_t i = 0; i < N; ++i)
    if (!layers[i].exact()) return static_cast<int>(i);
  return -1;
}

// N symbol models made on first use (most contexts of a chunk never occur).
template <std::size_t N>
class LazyModels {
 public:
  explicit LazyModels(std::uint32_t symbols) : symbols_(symbols) {}
  SymbolModel& operator[](std::size_t i) {
    std::unique_ptr<SymbolModel>& model = models_[i];
    if (!model) model = std::make_unique<SymbolModel>(symbols_);
    return *model;
  }
  void reset() {
    for (auto& model : models_)
      if (model) model->reset();
  }

 private:
  std::uint32_t symbols_;
  std::array<std::unique_ptr<SymbolModel>, N> models_;
};

std::int32_t mulWrapping(std::int32_t a, std::int32_t b) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(a) * static_cast<std::uint32_t>(b));
}

// GPS time version 3's codes: without a last difference, 0 a 32-bit difference, 1 a whole time,
// 2 to 4 a switch to another sequence; with one, 0 to kMulti - 1 and the negative multipliers down
// to kMultiMinus as in version 2, then a whole time and the switches.
constexpr std::int32_t kMulti = kGpsMulti;
constexpr std::int32_t kMultiMinus = kGpsMultiMinus;
constexpr std::uint32_t kMultiCodeFull = kMulti - kMultiMinus + 1;
constexpr std::uint32_t kMultiTotal = kMulti - kMultiMinus + 5;
constexpr int kMaxSwitches = 4;  // an encoder switches once per point at most

struct Point14Context {
  bool used = false;
  bool gps_changed = false;  // the last point's GPS time differed from the one before
  std::array<std::uint8_t, kPoint14Bytes> last{};
  // the "returns, x and y" layer
  std::array<SymbolModel, 8> changed = symbolModels<8>(128);
  SymbolModel channel{3};
  LazyModels<16> return_count{16}, return_number{16};
  SymbolModel return_number_same_time{13};
  IntegerModels dx{32, 2}, dy{32, 22};
  std::array<Median5, 12> x_median, y_median;
  // z
  IntegerModels z{32, 20};
  std::array<std::int32_t, 8> last_z{};
  // classification, flags, user data
  LazyModels<64> classes{256}, flags{64}, user_data{256};
  // intensity, scan angle, point source
  IntegerModels intensity{16, 4}, scan_angle{16, 2}, source_id{16, 1};
  std::array<std::uint16_t, 8> last_intensity{};
  // GPS time: up to four interleaved sequences
  SymbolModel gps_multi{kMultiTotal}, gps_zero_diff{5};
  IntegerModels gps{32, 9};
  std::uint32_t gps_last = 0, gps_next = 0;
  std::array<std::uint64_t, 4> gps_times{};
  std::array<std::int32_t, 4> gps_diff{}, gps_extreme{};

  void reset(const std::uint8_t* item) {
    for (auto& model : changed) model.reset();
    channel.reset();
    return_count.reset();
    return_number.reset();
    return_number_same_time.reset();
    dx.reset();
    dy.reset();
    for (auto& m : x_median) m.reset();
    for (auto& m : y_median) m.reset();
    z.reset();
    last_z.fill(load<std::int32_t>(item + kZ));
    classes.reset();
    flags.reset();
    user_data.reset();
    intensity.reset();
    scan_angle.reset();
    source_id.reset();
    last_intensity.fill(load<std::uint16_t>(item + kIntensity));
    gps_multi.reset();
    gps_zero_diff.reset();
    gps.reset();
    gps_last = gps_next = 0;
    gps_times = {load<std::uint64_t>(item + kGpsTime14), 0, 0, 0};
    gps_diff = {};
    gps_extreme = {};
    std::memcpy(last.data(), item, kPoint14Bytes);
    gps_changed = false;
    used = true;
  }
};

class Point14V3 final : public LayeredItemDecoder {
 public:
  // The first layer (returns, x and y) is always decoded: every other layer's contexts read it.
  explicit Point14V3(RecordFields fields)
      : wanted_{true,
                fields.has(RecordField::kZ),
                fields.has(RecordField::kClassification),
                fields.has(RecordField::kFlags),
                fields.has(RecordField::kIntensity),
                fields.has(RecordField::kScanAngle),
                fields.has(RecordField::kUserData),
                fields.has(RecordField::kPointSource),
                fields.has(RecordField::kGpsTime)} {}
  std::size_t layerCount() const override { return kLayers; }

  void start(const std::uint8_t* first, std::span<const std::span<const std::uint8_t>> layers,
             std::uint32_t channel) override {
    for (std::size_t i = 0; i < kLayers; ++i) layers_[i].start(layers[i], wanted_[i]);
    contexts_.forget();
    current_ = channel;
    contexts_[current_].reset(first);
  }

  void decode(std::uint8_t* item, std::uint32_t& channel) override {
    // Each layer's decoder is copied into a local variable while it decodes, and back: so its
    // state stays in registers (codegen/laz_arithmetic.h).
    ArithmeticDecoder xy = layers_[kXy].decoder();
    Point14Context* c = &contexts_[current_];
    std::uint32_t last_number = c->last[kReturns] & 15u;
    std::uint32_t last_count = c->last[kReturns] >> 4;
    // the last point's return (first? last?) and whether its time changed choose the model
    const std::uint32_t last_return = (last_number == 1 ? 1u : 0u) |
                                      (last_number >= last_count ? 2u : 0u) |
                                      (c->gps_changed ? 4u : 0u);
    const std::uint32_t changed = xy.decodeSymbol(c->changed[last_return]);
    if (changed & 64) {  // another scanner channel
      const std::uint32_t next = (current_ + xy.decodeSymbol(c->channel) + 1) & 3u;
      if (!contexts_.used(next)) contexts_[next].reset(c->last.data());
      current_ = next;
      c = &contexts_[current_];
      c->last[kFlags14] = static_cast<std::uint8_t>((c->last[kFlags14] & 0xcf) | (next << 4));
      last_number = c->last[kReturns] & 15u;
      last_count = c->last[kReturns] >> 4;
      channel = current_;
    }
    std::uint8_t* last = c->last.data();
    const bool source_changed = changed & 32;
    const bool gps_changed = changed & 16;
    const bool scan_angle_changed = changed & 8;
    const std::uint32_t count =
        (changed & 4) ? xy.decodeSymbol(c->return_count[last_count]) : last_count;
    std::uint32_t number = last_number;
    switch (changed & 3) {
      case 1:
        number = (last_number + 1) & 15u;
        break;
      case 2:
        number = (last_number + 15) & 15u;
        break;
      case 3:
        number = gps_changed
                     ? xy.decodeSymbol(c->return_number[last_number])
                     : (last_number + xy.decodeSymbol(c->return_number_same_time) + 2) & 15u;
        break;
      default:
        break;
    }
    last[kReturns] = static_cast<std::uint8_t>(number | (count << 4));
    const std::uint32_t m = (std::uint32_t{kReturnMap6[count][number]} << 1) | gps_changed;
    const std::uint32_t level = returnLevel8(count, number);
    // single (3), first (2), last (1) or intermediate (0) return
    const std::uint32_t position = (number == 1 ? 2u : 0u) | (number >= count ? 1u : 0u);
    const std::uint32_t single = count == 1;

    const std::int32_t dx = c->dx.decode(xy, c->x_median[m].get(), single);
    store(last + kX, static_cast<std::int32_t>(load<std::uint32_t>(last + kX) +
                                               static_cast<std::uint32_t>(dx)));
    c->x_median[m].add(dx);
    std::uint32_t k = c->dx.k();
    const std::int32_t dy =
        c->dy.decode(xy, c->y_median[m].get(), single + (k < 20 ? evenBelow(k) : 20));
    store(last + kY, static_cast<std::int32_t>(load<std::uint32_t>(last + kY) +
                                               static_cast<std::uint32_t>(dy)));
    c->y_median[m].add(dy);
    layers_[kXy].decoder() = xy;

    if (layers_[kZLayer].present()) {
      k = (c->dx.k() + c->dy.k()) / 2;
      ArithmeticDecoder d = layers_[kZLayer].decoder();
      const std::int32_t z =
          c->z.decode(d, c->last_z[level], single + (k < 18 ? evenBelow(k) : 18));
      layers_[kZLayer].decoder() = d;
      store(last + kZ, z);
      c->last_z[level] = z;
    }
    if (layers_[kClassLayer].present()) {
      const std::uint32_t context = ((last[kClass14] & 0x1fu) << 1) | (position == 3 ? 1u : 0u);
      last[kClass14] = static_cast<std::uint8_t>(
          layers_[kClassLayer].decoder().decodeSymbol(c->classes[context]));
    }
    if (layers_[kFlagsLayer].present()) {
      // coded as classification flags (0-3), scan direction (4), edge of flight line (5)
      const std::uint8_t byte = last[kFlags14];
      const std::uint32_t context = (byte & 15u) | (((byte >> 6) & 1u) << 4) | ((byte >> 7) << 5);
      const std::uint32_t flags = layers_[kFlagsLayer].decoder().decodeSymbol(c->flags[context]);
      last[kFlags14] = static_cast<std::uint8_t>(
          (flags & 15u) | (byte & 0x30u) | (((flags >> 4) & 1u) << 6) | (((flags >> 5) & 1u) << 7));
    }
    if (layers_[kIntensityLayer].present()) {
      const std::uint32_t context = (position << 1) | gps_changed;
      ArithmeticDecoder d = layers_[kIntensityLayer].decoder();
      c->last_intensity[context] =
          static_cast<std::uint16_t>(c->intensity.decode(d, c->last_intensity[context], position));
      layers_[kIntensityLayer].decoder() = d;
      store(last + kIntensity, c->last_intensity[context]);
    }
    if (layers_[kScanAngleLayer].present() && scan_angle_changed) {
      store(last + kScanAngle14, static_cast<std::uint16_t>(c->scan_angle.decode(
                                     layers_[kScanAngleLayer].decoder(),
                                     load<std::int16_t>(last + kScanAngle14), gps_changed)));
    }
    if (layers_[kUserDataLayer].present()) {
      last[kUserData14] = static_cast<std::uint8_t>(
          layers_[kUserDataLayer].decoder().decodeSymbol(c->user_data[last[kUserData14] / 4]));
    }
    if (layers_[kSourceLayer].present() && source_changed) {
      store(last + kSourceId14,
            static_cast<std::uint16_t>(c->source_id.decode(
                layers_[kSourceLayer].decoder(), load<std::uint16_t>(last + kSourceId14), 0)));
    }
    if (layers_[kGpsLayer].present() && gps_changed) {
      ArithmeticDecoder d = layers_[kGpsLayer].decoder();
      for (int switches = 0; switches < kMaxSwitches; ++switches) {
        if (decodeTime(d, *c)) break;
      }
      layers_[kGpsLayer].decoder() = d;
      store(last + kGpsTime14, c->gps_times[c->gps_last]);
    }
    std::memcpy(item, last, kPoint14Bytes);
    c->gps_changed = gps_changed;
  }

  int overrunLayer() const override { return layers_[kXy].overrun() ? 0 : -1; }
  int inexactLayer() const override { return firstInexact(layers_); }
  std::string layerName(std::size_t layer) const override {
    static constexpr const char* kNames[kLayers] = {
        "returns, x and y", "z",         "classification", "flags",   "intensity",
        "scan angle",       "user data", "point source",   "GPS time"};
    return std::string("POINT14 layer ") + kNames[layer];
  }

 private:
  enum : std::size_t {
    kXy,
    kZLayer,
    kClassLayer,
    kFlagsLayer,
    kIntensityLayer,
    kScanAngleLayer,
    kUserDataLayer,
    kSourceLayer,
    kGpsLayer,
    kLayers
  };

  // A difference of a multiple of the last one; repeated extremes replace the last difference.
  static void addTime(Point14Context& c, std::int32_t diff, bool extreme) {
    if (extreme && ++c.gps_extreme[c.gps_last] > 3) {
      c.gps_diff[c.gps_last] = diff;
      c.gps_extreme[c.gps_last] = 0;
    }
    c.gps_times[c.gps_last] += static_cast<std::uint64_t>(static_cast<std::int64_t>(diff));
  }

  // A whole new time in a new sequence: its high 32 bits predicted by the current one's.
  __attribute__((always_inline)) static void fullTime(ArithmeticDecoder& d, Point14Context& c) {
    c.gps_next = (c.gps_next + 1) & 3;
    const auto high = static_cast<std::uint32_t>(
        c.gps.decode(d, static_cast<std::int32_t>(c.gps_times[c.gps_last] >> 32), 8));
    c.gps_times[c.gps_next] = (std::uint64_t{high} << 32) | d.readInt();
    c.gps_last = c.gps_next;
    c.gps_diff[c.gps_last] = 0;
    c.gps_extreme[c.gps_last] = 0;
  }

  // One step of the time's code; false when it switched sequences and the time is still to come.
  __attribute__((always_inline)) static bool decodeTime(ArithmeticDecoder& d, Point14Context& c) {
    std::int32_t& last_diff = c.gps_diff[c.gps_last];
    if (last_diff == 0) {
      const std::uint32_t multi = d.decodeSymbol(c.gps_zero_diff);
      if (multi == 0) {
        last_diff = c.gps.decode(d, 0, 0);
        c.gps_times[c.gps_last] += static_cast<std::uint64_t>(std::int64_t{last_diff});
        c.gps_extreme[c.gps_last] = 0;
      } else if (multi == 1) {
        fullTime(d, c);
      } else {
        c.gps_last = (c.gps_last + multi - 1) & 3;
        return false;
      }
      return true;
    }
    const std::uint32_t multi = d.decodeSymbol(c.gps_multi);
    if (multi == 1) {
      c.gps_times[c.gps_last] +=
          static_cast<std::uint64_t>(std::int64_t{c.gps.decode(d, last_diff, 1)});
      c.gps_extreme[c.gps_last] = 0;
    } else if (multi < kMultiCodeFull) {
      if (multi == 0) {
        addTime(c, c.gps.decode(d, 0, 7), true);
      } else if (multi < static_cast<std::uint32_t>(kMulti)) {
        const std::int32_t prediction = mulWrapping(static_cast<std::int32_t>(multi), last_diff);
        addTime(c, c.gps.decode(d, prediction, multi < 10 ? 2 : 3), false);
      } else if (multi == static_cast<std::uint32_t>(kMulti)) {
        addTime(c, c.gps.decode(d, mulWrapping(kMulti, last_diff), 4), true);
      } else {
        const std::int32_t negative = kMulti - static_cast<std::int32_t>(multi);
        if (negative > kMultiMinus) {
          addTime(c, c.gps.decode(d, mulWrapping(negative, last_diff), 5), false);
        } else {
          addTime(c, c.gps.decode(d, mulWrapping(kMultiMinus, last_diff), 6), true);
        }
      }
    } else if (multi == kMultiCodeFull) {
      fullTime(d, c);
    } else {
      c.gps_last = (c.gps_last + multi - kMultiCodeFull) & 3;
      return false;
    }
    return true;
  }

  std::array<bool, kLayers> wanted_;
  std::array<Layer, kLayers> layers_;
  ChannelContexts<Point14Context> contexts_;
  std::uint32_t current_ = 0;
};

// RGB14 (colour) and RGBNIR14 (colour and near infrared, a layer each).
class Rgb14V3 final : public LayeredItemDecoder {
 public:
  Rgb14V3(bool nir, RecordFields fields)
      : nir_(nir),
        want_rgb_(fields.has(RecordField::kRgb)),
        want_nir_(fields.has(RecordField::kNir)) {}
  std::size_t layerCount() const override { return nir_ ? 2 : 1; }

  void start(const std::uint8_t* first, std::span<const std::span<const std::uint8_t>> layers,
             std::uint32_t channel) override {
    rgb_.start(layers[0], want_rgb_);
    if (nir_) nir_layer_.start(layers[1], want_nir_);
    std::array<std::uint8_t, 8> first_item{};
    std::memcpy(first_item.data(), first, nir_ ? 8 : 6);
    follower_.start(first_item.data(), channel);
  }

  void decode(std::uint8_t* item, std::uint32_t& channel) override {
    auto [c, last] = follower_.follow(channel);
    if (rgb_.present()) decodeRgb(rgb_.decoder(), c->rgb, last, last);
    std::memcpy(item, last, 6);
    if (!nir_) return;
    if (nir_layer_.present()) {
      ArithmeticDecoder& d = nir_layer_.decoder();
      const std::uint32_t used = d.decodeSymbol(c->nir_used);
      for (std::size_t byte = 0; byte < 2; ++byte) {
        if (used & (1u << byte)) {
          last[6 + byte] = foldByte(last[6 + byte] +
                                    static_cast<std::int32_t>(d.decodeSymbol(c->nir_diff[byte])));
        }
      }
    }
    std::memcpy(item + 6, last + 6, 2);
  }

  int overrunLayer() const override { return rgb_.overrun() ? 0 : nir_layer_.overrun() ? 1 : -1; }
  int inexactLayer() const override { return !rgb_.exact() ? 0 : !nir_layer_.exact() ? 1 : -1; }
  std::string layerName(std::size_t layer) const override {
    return std::string(nir_ ? "RGBNIR14" : "RGB14") + (layer == 0 ? " layer RGB" : " layer NIR");
  }

 private:
  bool nir_;
  bool want_rgb_, want_nir_;
  Layer rgb_, nir_layer_;
  ChannelFollower<RgbContext> follower_;
};

struct WavePacketContext {
  bool used = false;
  std::array<std::uint8_t, kWavePacketBytes> last{};
  WavePacketModels models;
  void reset(const std::uint8_t* item) {
    models.reset();
    std::memcpy(last.data(), item, last.size());
    used = true;
  }
};

class WavePacket14V3 final : public LayeredItemDecoder {
 public:
  explicit WavePacket14V3(RecordFields fields) : wanted_(fields.has(RecordField::kWavePacket)) {}
  std::size_t layerCount() const override { return 1; }
  void start(const std::uint8_t* first, std::span<const std::span<const std::uint8_t>> layers,
             std::uint32_t channel) override {
    layer_.start(layers[0], wanted_);
    follower_.start(first, channel);
  }
  void decode(std::uint8_t* item, std::uint32_t& channel) override {
    auto [c, last] = follower_.follow(channel);
    if (layer_.present()) decodeWavePacket(layer_.decoder(), c->models, last, last);
    std::memcpy(item, last, kWavePacketBytes);
  }
  int overrunLayer() const override { return layer_.overrun() ? 0 : -1; }
  int inexactLayer() const override { return layer_.exact() ? -1 : 0; }
  std::string layerName(std::size_t) const override { return "WAVEPACKET14 layer"; }

 private:
  bool wanted_;
  Layer layer_;
  ChannelFollower<WavePacketContext> follower_;
};

// BYTE14 (extra bytes): a layer per byte, each byte's difference from the last point's.
class Bytes14V3 final : public LayeredItemDecoder {
 public:
  Bytes14V3(std::size_t count, RecordFields fields)
      : layers_(count), count_(count), wanted_(fields.has(RecordField::kExtraBytes)) {}
  std::size_t layerCount() const override { return count_; }

  void start(const std::uint8_t* first, std::span<const std::span<const std::uint8_t>> layers,
             std::uint32_t channel) override {
    for (std::size_t i = 0; i < count_; ++i) layers_[i].start(layers[i], wanted_);
    for (BytesContext& context : contexts_) context.used = false;
    current_ = channel & 3;
    reset(current_, first);
  }

  void decode(std::uint8_t* item, std::uint32_t& channel) override {
    // the same channel rule as ChannelFollower, with contexts sized by the byte count
    std::uint8_t* last = contexts_[current_].last.data();
    if (channel != current_) {
      current_ = channel & 3;
      if (!contexts_[current_].used) {
        reset(current_, last);
        last = contexts_[current_].last.data();
      }
    }
    BytesContext& c = contexts_[current_];
    for (std::size_t i = 0; i < count_; ++i) {
      if (layers_[i].present()) {
        last[i] = foldByte(
            last[i] + static_cast<std::int32_t>(layers_[i].decoder().decodeSymbol(c.models[i])));
      }
    }
    std::memcpy(item, last, count_);
  }

  int overrunLayer() const override {
    for (std::size_t i = 0; i < count_; ++i)
      if (layers_[i].overrun()) return static_cast<int>(i);
    return -1;
  }
  int inexactLayer() const override {
    for (std::size_t i = 0; i < count_; ++i)
      if (!layers_[i].exact()) return static_cast<int>(i);
    return -1;
  }
  std::string layerName(std::size_t layer) const override {
    return "BYTE14 layer " + std::to_string(layer + 1);
  }

 private:
  void reset(std::uint32_t channel, const std::uint8_t* item) {
    contexts_[channel].reset(item, count_);
  }

  std::vector<Layer> layers_;
  std::size_t count_;
  bool wanted_;
  std::array<BytesContext, 4> contexts_;
  std::uint32_t current_ = 0;
};

}  // namespace

std::unique_ptr<LayeredItemDecoder> layeredDecoder(const Item& item, RecordFields fields) {
  if (item.version != 3) return nullptr;
  switch (item.type) {
    case ItemType::kPoint14:
      return std::make_unique<Point14V3>(fields);
    case ItemType::kRgb14:
      return std::make_unique<Rgb14V3>(false, fields);
    case ItemType::kRgbNir14:
      return std::make_unique<Rgb14V3>(true, fields);
    case ItemType::kWavePacket14:
      return std::make_unique<WavePacket14V3>(fields);
    case ItemType::kByte14:
      return item.size > 0 ? std::make_unique<Bytes14V3>(item.size, fields) : nullptr;
    default:
      return nullptr;
  }
}

}  // namespace octopoint::laz
