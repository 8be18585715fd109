#pragma once
// The layered LAZ items (LASzip's compressor 3, item version 3, LAS point formats 6 to 10): a
// chunk stores its first point raw, then its point count, then the byte size of every layer, then
// the layers. Each layer is an arithmetic stream of its own holding one field of every point of the
// chunk (POINT14 has nine: the return counts with x and y, z, classification, flags, intensity,
// scan angle, user data, point source, GPS time; RGB14 one, RGBNIR14 two, WAVEPACKET14 one, BYTE14
// one per byte), so that a reader may leave out the layers it does not need (a decoder is told
// which, codegen/record_fields.h, and steps over the others by their sizes). An empty layer means
// the field never changes within the chunk.
//
// The predictions keep four contexts, one per scanner channel: the "changed values" symbol of
// POINT14 says, among others, when the channel changes, and every item follows the channel that
// POINT14 decoded. A channel's context starts from the point before its first point.

#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "codegen/laz_pointwise.h"
#include "codegen/record_fields.h"

namespace octopoint::laz {

// One item of the layered compressor, decoding a chunk's points from its layers.
class LayeredItemDecoder {
 public:
  virtual ~LayeredItemDecoder() = default;
  // The layers of the item in a chunk (and so the 32-bit sizes it has in the chunk's head).
  virtual std::size_t layerCount() const = 0;
  // Starts a chunk: its first point's item, the item's layers, the first point's scanner channel.
  virtual void start(const std::uint8_t* first,
                     std::span<const std::span<const std::uint8_t>> layers,
                     std::uint32_t channel) = 0;
  // Decodes the next point's item. The caller sets `channel` to 0 before each point; POINT14
  // (which goes first) sets it to the point's scanner channel when the channel changes, and only
  // then; the other items take their context from it. So on the points after a switch they are
  // told channel 0, whatever the channel is: LASzip, which defines the format, passes them the
  // context that way, and laz-perf follows it.
  virtual void decode(std::uint8_t* item, std::uint32_t& channel) = 0;
  // The layer that read past its bytes so far, or -1 (checked as the points go, to stop a corrupt
  // chunk early).
  virtual int overrunLayer() const = 0;
  // After a whole chunk: the first layer whose code did not end exactly at its last byte or held
  // a raw value out of range, or -1.
  virtual int inexactLayer() const = 0;
  // A layer's name for messages, e.g. "POINT14 layer z".
  virtual std::string layerName(std::size_t layer) const = 0;
};

// The decoder of a layered item, or nullptr for a type or version this reader does not know. It
// decodes the layers of `fields` only (codegen/record_fields.h), and always POINT14's first.
std::unique_ptr<LayeredItemDecoder> layeredDecoder(
    const Item& item, prepare::RecordFields fields = prepare::RecordFields::all());

}  // namespace octopoint::laz
