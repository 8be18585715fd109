#pragma once
// The point-wise LAZ items (LAS point formats 0 to 5): each point record is cut into items
// (POINT10, the 20 bytes every format has; GPSTIME11; RGB12; WAVEPACKET13; BYTE, the extra bytes),
// and each item is predicted from the same item of the previous point of the chunk, all items of a
// point coded in one arithmetic stream. Versions 1 (LASzip 1.x) and 2 (LASzip 2 and later,
// laz-perf) of each item differ in their predictions and contexts.

#include <array>
#include <cstdint>
#include <memory>
#include <string>

#include "codegen/laz_arithmetic.h"
#include "codegen/laz_integer.h"

namespace octopoint::laz {

enum class ItemType : std::uint16_t {
  kByte = 0,
  kPoint10 = 6,
  kGpsTime11 = 7,
  kRgb12 = 8,
  kWavePacket13 = 9,
  kPoint14 = 10,
  kRgb14 = 11,
  kRgbNir14 = 12,
  kWavePacket14 = 13,
  kByte14 = 14,
};

struct Item {
  ItemType type = ItemType::kByte;
  std::uint16_t size = 0;  // bytes of the record
  std::uint16_t version = 0;
};

std::string itemName(const Item& item);  // e.g. "RGB12 version 2"

// Decodes one item of every point of a chunk from the chunk's arithmetic stream.
class ItemDecoder {
 public:
  virtual ~ItemDecoder() = default;
  // The chunk's first point, stored raw: the predictions start from it.
  virtual void start(const std::uint8_t* first) = 0;
  virtual void decode(std::uint8_t* item) = 0;
};

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

// The decoder of a point-wise item, or nullptr for a type or version this reader does not know.
std::unique_ptr<ItemDecoder> pointwiseDecoder(const Item& item, ArithmeticDecoder& decoder);

}  // namespace octopoint::laz
