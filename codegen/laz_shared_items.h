#pragma once
// The colour and wave-packet coding that LAZ's point-wise items (RGB12 version 2, WAVEPACKET13
// version 1: codegen/laz_pointwise.h) and layered items (RGB14, RGBNIR14, WAVEPACKET14 version 3:
// codegen/laz_layered.h) share: the same models and predictions, in one arithmetic stream or in
// a layer's.

#include <array>
#include <cstddef>
#include <cstdint>

#include "codegen/laz_arithmetic.h"
#include "codegen/laz_integer.h"

namespace octopoint::laz {

// The colour models of RGB12 version 2 and of the layered RGB14 and RGBNIR14 (which code a
// colour alike).
struct RgbModels {
  void reset();
  SymbolModel used{128};
  std::array<SymbolModel, 6> diff{SymbolModel(256), SymbolModel(256), SymbolModel(256),
                                  SymbolModel(256), SymbolModel(256), SymbolModel(256)};
};

// Decodes a colour (red, green, blue: 6 bytes) predicted from `last`; `out` may be `last`.
void decodeRgb(ArithmeticDecoder& decoder, RgbModels& models, const std::uint8_t* last,
               std::uint8_t* out);

// A wave packet item: descriptor index, offset (uint64), size (uint32), return point and x, y, z
// (four float32, coded as their bits).
inline constexpr std::size_t kWavePacketBytes = 29;

// The models of WAVEPACKET13 version 1 and WAVEPACKET14 version 3 (which code a packet alike).
struct WavePacketModels {
  void reset();
  std::int32_t last_diff = 0;
  std::uint32_t last_offset_symbol = 0;
  SymbolModel index{256};
  std::array<SymbolModel, 4> offset_kind{SymbolModel(4), SymbolModel(4), SymbolModel(4),
                                         SymbolModel(4)};
  IntegerModels offset_diff{32, 1}, size{32, 1}, return_point{32, 1}, xyz{32, 3};
};

// Decodes a wave packet predicted from `last`; `out` may be `last`.
void decodeWavePacket(ArithmeticDecoder& decoder, WavePacketModels& models,
                      const std::uint8_t* last, std::uint8_t* out);

}  // namespace octopoint::laz
