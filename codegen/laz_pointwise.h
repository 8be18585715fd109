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
#include "codegen/laz_shared_items.h"

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

// The decoder of a point-wise item, or nullptr for a type or version this reader does not know.
std::unique_ptr<ItemDecoder> pointwiseDecoder(const Item& item, ArithmeticDecoder& decoder);

}  // namespace octopoint::laz
