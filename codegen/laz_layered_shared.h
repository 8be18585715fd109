#pragma once
// What the layered LAZ items (codegen/laz_layered.h) share between their decoder
// (codegen/laz_layered.cpp) and the tests' encoder (tests/support/laz_encoder.cpp): POINT14's
// fields and return contexts, the scanner channels' contexts, and the colour items' context. Both
// sides must compute them alike.

#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <utility>
#include <vector>

#include "codegen/laz_arithmetic.h"
#include "codegen/laz_pointwise.h"

namespace octopoint::laz {

template <std::size_t N, std::size_t... I>
std::array<SymbolModel, N> symbolModels(std::uint32_t symbols, std::index_sequence<I...>) {
  return {(static_cast<void>(I), SymbolModel(symbols))...};
}
template <std::size_t N>
std::array<SymbolModel, N> symbolModels(std::uint32_t symbols) {
  return symbolModels<N>(symbols, std::make_index_sequence<N>{});
}

// POINT14's fields (LAS "Point Data Record Format 6").
// kReturns: return number (low 4 bits), number of returns (high 4)
inline constexpr std::size_t kReturns = 14;
inline constexpr std::size_t kFlags14 = 15;  // classification flags (0-3), channel (4-5), scan
                                             // direction, edge of flight line
inline constexpr std::size_t kClass14 = 16, kUserData14 = 17, kScanAngle14 = 18, kSourceId14 = 20,
                             kGpsTime14 = 22, kPoint14Bytes = 30;

// Contexts by (number of returns, return number) for x and y (6 of them) and z (8: the distance
// from the last return).
inline constexpr std::uint8_t kReturnMap6[16][16] = {
    {0, 1, 2, 3, 4, 5, 3, 4, 4, 5, 5, 5, 5, 5, 5, 5},
    {1, 0, 1, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3},
    {2, 1, 2, 4, 4, 4, 4, 4, 4, 4, 4, 3, 3, 3, 3, 3},
    {3, 3, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4},
    {4, 3, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4},
    {5, 3, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4},
    {3, 3, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4, 4},
    {4, 3, 4, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4, 4},
    {4, 3, 4, 4, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4, 4},
    {5, 3, 4, 4, 4, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4, 4},
    {5, 3, 4, 4, 4, 4, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4},
    {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 4, 4, 4},
    {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 5, 4, 4},
    {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 5, 4},
    {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 5},
    {5, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 5, 5}};

inline std::uint32_t returnLevel8(std::uint32_t count, std::uint32_t number) {
  const std::uint32_t level = count > number ? count - number : number - count;
  return level < 7 ? level : 7;
}

// The four scanner channels' contexts of an item, each made when its channel first occurs.
template <typename Context>
class ChannelContexts {
 public:
  Context& operator[](std::uint32_t channel) {
    std::unique_ptr<Context>& context = contexts_[channel & 3];
    if (!context) context = std::make_unique<Context>();
    return *context;
  }
  bool used(std::uint32_t channel) const {
    return contexts_[channel & 3] && contexts_[channel & 3]->used;
  }
  void forget() {
    for (auto& context : contexts_)
      if (context) context->used = false;
  }

 private:
  std::array<std::unique_ptr<Context>, 4> contexts_;
};

// The items after POINT14 follow its channel. LASzip, which defines the format, moves such an
// item's "last" to a channel's context only when that context is new: on a switch back to a
// channel seen before, the prediction still starts from the previous channel's last value (and
// the decoded value is stored there). The decoders here do the same, or they would decode another
// file than the one written.
template <typename Context>
class ChannelFollower {
 public:
  // The context to decode with and the last value to predict from, after `channel`'s switch.
  std::pair<Context*, std::uint8_t*> follow(std::uint32_t channel) {
    std::uint8_t* last = contexts_[current_].last.data();
    if (channel != current_) {
      current_ = channel;
      if (!contexts_.used(current_)) {
        contexts_[current_].reset(last);
        last = contexts_[current_].last.data();
      }
    }
    return {&contexts_[current_], last};
  }
  void start(const std::uint8_t* first, std::uint32_t channel) {
    contexts_.forget();
    current_ = channel;
    contexts_[current_].reset(first);
  }

 private:
  ChannelContexts<Context> contexts_;
  std::uint32_t current_ = 0;
};

// RGB14's and RGBNIR14's context of a scanner channel.
struct RgbContext {
  bool used = false;
  std::array<std::uint8_t, 8> last{};  // red, green, blue (and near infrared)
  RgbModels rgb;
  SymbolModel nir_used{4};
  std::array<SymbolModel, 2> nir_diff = symbolModels<2>(256);
  void reset(const std::uint8_t* item) {
    rgb.reset();
    nir_used.reset();
    for (auto& model : nir_diff) model.reset();
    std::memcpy(last.data(), item, last.size());
    used = true;
  }
};

// BYTE14's context of a scanner channel: the last bytes and a model per byte.
struct BytesContext {
  bool used = false;
  std::vector<std::uint8_t> last;
  std::vector<SymbolModel> models;
  void reset(const std::uint8_t* item, std::size_t count) {
    if (models.size() != count) models.assign(count, SymbolModel(256));
    for (SymbolModel& model : models) model.reset();
    std::vector<std::uint8_t> copy(item, item + count);  // `item` may be another context's last
    last = std::move(copy);
    used = true;
  }
};

}  // namespace octopoint::laz
