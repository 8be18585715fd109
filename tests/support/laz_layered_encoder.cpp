// The tests' layered LAZ item encoders (tests/support/laz_layered_encoder.h).

#include "tests/support/laz_layered_encoder.h"

#include <array>
#include <cstring>
#include <memory>
#include <vector>

#include "tests/support/laz_shared_encoders.h"

namespace octopoint::testing {
namespace {

using namespace octopoint::laz;

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

}  // namespace

std::unique_ptr<LayeredEncoder> makePoint14Layered() { return std::make_unique<Point14Layered>(); }
std::unique_ptr<LayeredEncoder> makeColourLayered(bool nir) {
  return std::make_unique<ColourLayered>(nir);
}
std::unique_ptr<LayeredEncoder> makeBytesLayered(std::size_t bytes) {
  return std::make_unique<BytesLayered>(bytes);
}

}  // namespace octopoint::testing
