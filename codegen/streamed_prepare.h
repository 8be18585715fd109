#pragma once
// The preparer out of core and in parallel: any number of points in a bounded memory budget, on
// every core, with output identical byte for byte whatever the budget and the thread count.
//
//   pass 1  read every point: count, drop the non-finite, crop, turn the axes, bound them (and
//           count intensities, and find whether LAS colours are 8- or 16-bit)
//   pass 2  read every point again (a compressed file's from pass 1's decoded copy on disk,
//           codegen/decoded_points.h): its Morton key at the finest depth, binned by the key's top
//           digits into buffers that go to a temporary file as they fill (--memory)
//   or one pass, when a LAS or LAZ header states a box and nothing is cropped: pass 2's binning
//           on the cube of the header's box, while tallying what pass 1 would have; when the
//           points' own bounds give another cube (a header that lies, or loose), or every colour
//           is 0, the bins are dropped and pass 2 runs on the tally: a second reading, never a
//           different model
//   bins    each bin, a node of the octree, sorted and voxelized on its own (in parallel); a bin
//           too large for a thread's share of the budget is binned again, one level deeper
//   join    the bins' subtrees joined into each depth's stream, the palette made from the finest
//           depth's colours, pruning if asked (codegen/model_assembly.h)
//
// The points are summed per voxel as integers, so the order in which threads see them, and where
// the buffers filled up, change nothing (tests/preparer/streamed_prepare_test.cpp checks budgets
// and thread counts against each other and against the in-memory reference, codegen/voxelizer.h).

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>

#include "codegen/point_source.h"
#include "codegen/prepare.h"
#include "codegen/prepared_model.h"

namespace octopoint::prepare {

inline constexpr std::uint64_t kDefaultMemoryBytes = std::uint64_t{1} << 30;

struct StreamOptions {
  // For the points in flight: the pass 2 buffers (half) and the threads' bins (half). The model
  // itself (about 5 bytes per voxel of every depth, while it is being assembled), the read chunks
  // (2 MB per thread) and the histograms (1.5 MB per thread) come on top.
  std::uint64_t memory_bytes = kDefaultMemoryBytes;
  unsigned threads = 0;            // 0: every core
  std::filesystem::path temp_dir;  // empty: the system's temporary directory (TMPDIR, else /tmp)
  // When the bounds take a pass of their own (a crop; no header box): a compressed source's
  // points decoded once, in pass 1, and read back from a temporary file in pass 2 (when the disk
  // has room for them: else decoded twice). False: decoded in each pass.
  bool decode_once = true;
  // One pass on the header's box when the source states one (SourceInfo::header_box). False: the
  // bounds are always taken in a pass of their own.
  bool header_box = true;
};

// What the run saw, for octopoint-prepare's summary.
struct PrepareSummary {
  std::uint64_t points_in_file = 0;
  std::uint64_t finite_points = 0;  // those not dropped as non-finite (before cropping)
  std::uint64_t dropped_non_finite = 0;
  std::uint64_t model_points = 0;  // those voxelized (after cropping)
  // A crop reads only the pieces that may meet it: all of them, but for COPC's octree nodes.
  std::uint64_t points_read = 0;
  std::size_t pieces_read = 0;
  std::size_t pieces = 0;
  std::uint64_t bytes_read = 0;  // of the file, by both passes (PointSource::bytesRead)
  ScanShading shading = ScanShading::kNone;
  std::string colour_note;  // e.g. "16-bit LAS colour"; empty if nothing to say
  std::uint64_t spilled_bytes = 0;
  std::uint64_t decoded_kept_bytes = 0;  // pass 1's decoded points kept on disk for pass 2
  unsigned source_passes = 0;   // how often the source was read (a LAZ chunk decoded): 1 or 2
  std::string header_box_note;  // why the header's box was tried and not taken; empty if it held
  unsigned threads = 0;
  double seconds = 0;
  // Wall time of: pass 1 (bounds), pass 2 (binning), voxelizing the bins, palette and leaves.
  std::array<double, 4> phase_seconds{};
};

// Prepares the model from `source` (named `path` in messages) as prepareModel does from a scan in
// memory, except outlier removal, which needs the whole scan: options.outliers must be empty.
// Throws PrepareError with one line for every failure.
PreparedModel prepareFromSource(const PointSource& source, const std::string& path,
                                const PrepareOptions& options, const StreamOptions& stream,
                                PrepareSummary* summary = nullptr);

}  // namespace octopoint::prepare
