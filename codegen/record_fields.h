#pragma once
// Which fields of a LAS point record a reader must decode. Only the layered LAZ chunks (point
// formats 6 to 10, codegen/laz_layered.h) can leave fields out: each field there has its own
// arithmetic-coded layer with its byte count in the chunk's head, so the layers of the fields not
// asked for are stepped over by their sizes and never decoded. A point-wise chunk (formats 0 to 5)
// and a LAS file hold every field in one stream and are read whole whatever is asked.
//
// X, Y, the return number and count and the scanner channel are always decoded: they share the
// first layer, and every other layer's prediction reads them (z's contexts take x's and y's
// coders' state, intensity's and classification's the return, every item the channel). Apart from
// that first layer, LASzip's layers depend on nothing but their own past values, so any of them
// may be left out alone. A field left out keeps, in every record of a chunk, whatever the decoder
// last stored there (the chunk's first point's value, or a value of another scanner channel): it
// is not the file's and must not be read.

#include <cstdint>

namespace octopoint::prepare {

enum class RecordField : std::uint32_t {
  kZ = 1u << 0,
  kClassification = 1u << 1,
  kFlags = 1u << 2,  // classification flags, scan direction, edge of flight line (not the channel)
  kIntensity = 1u << 3,
  kScanAngle = 1u << 4,
  kUserData = 1u << 5,
  kPointSource = 1u << 6,
  kGpsTime = 1u << 7,
  kRgb = 1u << 8,
  kNir = 1u << 9,
  kWavePacket = 1u << 10,
  kExtraBytes = 1u << 11,
};

class RecordFields {
 public:
  // Every field: the records exactly as the file holds them.
  static constexpr RecordFields all() { return RecordFields(~0u); }
  // X, y and the return and channel only (see above); add fields with `with`.
  static constexpr RecordFields xyOnly() { return RecordFields(0); }
  // What the preparer reads from a record (decodeLasRecords, PointChunk): the position, the
  // intensity and the colour.
  static constexpr RecordFields pointChunk() {
    return xyOnly().with(RecordField::kZ).with(RecordField::kIntensity).with(RecordField::kRgb);
  }

  constexpr RecordFields with(RecordField field) const {
    return RecordFields(bits_ | static_cast<std::uint32_t>(field));
  }
  constexpr RecordFields without(RecordField field) const {
    return RecordFields(bits_ & ~static_cast<std::uint32_t>(field));
  }
  constexpr bool has(RecordField field) const {
    return (bits_ & static_cast<std::uint32_t>(field)) != 0;
  }
  constexpr bool operator==(const RecordFields&) const = default;

 private:
  explicit constexpr RecordFields(std::uint32_t bits) : bits_(bits) {}
  std::uint32_t bits_;
};

}  // namespace octopoint::prepare
