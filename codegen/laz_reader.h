#pragma once
// LAZ read natively: a LAS file whose point records LASzip compressed, read without LASzip. The
// LAS header and VLRs are read as for LAS (codegen/las_reader.h); LASzip's VLR says how the records
// were cut into items and compressed; the point data is a series of chunks, each decodable alone
// (its first point stored raw, the rest arithmetic-coded from it), found through the chunk table
// that the first 8 bytes of the point data point to.
//
// The chunks are the source's pieces (PointSource::piece), so each pass decodes every chunk once,
// the chunks spread over the threads. Memory: per thread, one chunk's records and the decoder's
// models (about 2 MB), whatever the file's size.
//
// Everything in the file is untrusted: the VLR, the chunk table and every chunk are checked
// against the header and the file before use, a chunk that decodes past its bytes is refused, and
// each failure is one PrepareError line naming the file and the chunk.

#include <cstdint>
#include <memory>

#include "codegen/file_io.h"
#include "codegen/las_reader.h"
#include "codegen/point_source.h"
#include "codegen/record_fields.h"

namespace octopoint::prepare {

// The most points one chunk may have: a thread holds a chunk's records at once. LASzip writes
// 50,000 by default.
inline constexpr std::uint64_t kMaxLazChunkPoints = 1u << 20;

// The LAZ file whose LAS header is `header` (header.compressed) as a point source. Its layered
// chunks (formats 6 to 10) decode only `fields` into PointChunk::raw (codegen/record_fields.h);
// the fields PointChunk carries (RecordFields::pointChunk) must be among them.
std::unique_ptr<PointSource> openLazSource(std::unique_ptr<InputFile> file, const LasHeader& header,
                                           RecordFields fields);

}  // namespace octopoint::prepare
