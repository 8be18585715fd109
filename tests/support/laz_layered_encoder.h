#pragma once
// The tests' encoders of LAZ's layered items, version 3 (POINT14, RGB14, RGBNIR14, BYTE14), each
// the inverse of its decoder in codegen/laz_layered.cpp; tests/support/laz_encoder.cpp cuts chunks
// with them.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace octopoint::testing {

class LayeredEncoder {
 public:
  virtual ~LayeredEncoder() = default;
  virtual void start(const std::uint8_t* first, std::uint32_t channel) = 0;
  virtual void encode(const std::uint8_t* item, std::uint32_t channel) = 0;
  // Appends the item's layers, in order (empty ones included).
  virtual void finish(std::vector<std::vector<std::uint8_t>>& layers) = 0;
};

std::unique_ptr<LayeredEncoder> makePoint14Layered();
std::unique_ptr<LayeredEncoder> makeColourLayered(bool nir);  // RGBNIR14 with `nir`, else RGB14
std::unique_ptr<LayeredEncoder> makeBytesLayered(std::size_t bytes);

}  // namespace octopoint::testing
