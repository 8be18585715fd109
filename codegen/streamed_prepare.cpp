#include "codegen/streamed_prepare.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>

#include "cli/file_size_signal.h"
#include "cli/text.h"
#include "codegen/bin_voxelizer.h"
#include "codegen/cube_fit.h"
#include "codegen/decoded_points.h"
#include "codegen/file_io.h"
#include "codegen/intensity_grey.h"
#include "codegen/model_assembly.h"
#include "codegen/parallel.h"
#include "codegen/point_bins.h"
#include "codegen/point_tally.h"
#include "codegen/prepare_error.h"
#include "codegen/progress.h"
#include "codegen/sample_reach.h"
#include "codegen/scene_pruning.h"
#include "codegen/voxelizer.h"

namespace octopoint::prepare {
namespace {

namespace fs = std::filesystem;

// Bins are the nodes at this level (8^4 = 4096), or at the finest depth when it is shallower: small
// enough for a thread's share of the budget in any real scan, many enough to keep threads busy.
constexpr int kBinLevel = 4;
constexpr int kSubBinLevels = 2;  // a bin too large is split this many levels deeper
constexpr std::size_t kMinBinPoints = 1024;
// A worker voxelizing a bin holds per point: the point, a sort buffer, and its key.
constexpr std::uint64_t kBytesPerBinPoint = 2 * sizeof(BinnedPoint) + sizeof(std::uint64_t);

// Where spill files go: --temp-dir, else $TMPDIR, else /tmp.
fs::path temporaryDirectory(const fs::path& requested) {
  const char* from_environment = std::getenv("TMPDIR");
  if (!requested.empty()) return requested;
  return from_environment && *from_environment ? fs::path(from_environment) : fs::path("/tmp");
}

// Checked before any work when the points may not fit the budget.
void checkDirectory(const fs::path& directory) {
  std::error_code error;
  if (!fs::is_directory(directory, error)) {
    throw PrepareError(directory.string() +
                       ": not a directory, so no temporary files can go there (--temp-dir, "
                       "or TMPDIR)");
  }
}

// A point's colour binned as 8-bit when no channel of its chunk passes 255 and the file's choice
// was not yet known (one pass): bit 24 of the payload, above the colour's 0xRRGGBB.
constexpr std::uint32_t kEightBitMark = 1u << 24;

bool sameFit(const CubeFit& a, const CubeFit& b) {  // bit for bit: the cube the model records
  for (std::size_t axis = 0; axis < 3; ++axis) {
    if (std::bit_cast<std::uint64_t>(a.origin[axis]) !=
        std::bit_cast<std::uint64_t>(b.origin[axis]))
      return false;
  }
  return std::bit_cast<std::uint64_t>(a.edge) == std::bit_cast<std::uint64_t>(b.edge);
}

// Times the phases one after another into a PrepareSummary.
class PhaseClock {
 public:
  explicit PhaseClock(std::array<double, 4>& seconds) : seconds_(seconds) {}
  void next() {
    const auto now = std::chrono::steady_clock::now();
    seconds_[phase_++] = std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }

 private:
  std::array<double, 4>& seconds_;
  std::size_t phase_ = 0;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

class StreamedPreparer {
 public:
  StreamedPreparer(const PointSource& source, const std::string& path,
                   const PrepareOptions& options, const StreamOptions& stream)
      : source_(source),
        info_(source.info()),
        path_(path),
        options_(options),
        filter_(options.crop, options.axes, source.info().float_coordinates),
        threads_(threadCount(stream.threads)),
        temp_dir_(temporaryDirectory(stream.temp_dir)) {
    const std::uint64_t half = stream.memory_bytes / 2 / threads_;
    buffer_points_ = std::max<std::uint64_t>(half / sizeof(BinnedPoint), kMinBinPoints);
    bin_points_ = std::max<std::uint64_t>(half / kBytesPerBinPoint, kMinBinPoints);
    // A scan that fits the budget never writes a temporary file: it need not have a place for one.
    if (info_.points > std::min(threads_ * buffer_points_, bin_points_)) checkDirectory(temp_dir_);
    colouring_.depths = options.depths;
    colouring_.greyscale = options.greyscale;
    // A crop reads only the pieces that may meet it (COPC's nodes; every piece of other sources).
    for (std::size_t i = 0; i < source.pieceCount(); ++i) {
      if (!options.crop || source.pieceMayMeet(i, options.crop->low, options.crop->high)) {
        pieces_.push_back(i);
        points_read_ += source.piece(i).count;
      }
    }
    // One pass when the header states a box whose cube can be assumed: no crop (the box bounds
    // the points, not the points kept), a payload the pass can bin before it knows the file
    // (16-bit intensities counted exactly, or colour).
    if (stream.header_box && !options.crop && info_.header_box && info_.intensity_16bit &&
        info_.payload != PointPayload::kNone && !pieces_.empty()) {
      assumed_ = assumedFit();
    }
    // Room for the decoded copy and as much again for the bins' spills, else (also when no
    // temporary file can be made: a scan that fits the budget needs none) decode twice.
    if (!assumed_ && info_.compressed && stream.decode_once && !pieces_.empty() &&
        freeDiskBytes(temp_dir_) / 2 >= DecodedPoints::bytesFor(info_, points_read_)) {
      try {
        decoded_ = std::make_unique<DecodedPoints>(temp_dir_, source_.pieceCount());
      } catch (const PrepareError&) {
        decoded_.reset();
      }
    }
  }

  PreparedModel run(PrepareSummary& summary) {
    PhaseClock clock(summary.phase_seconds);
    if (!options_.crop) checkDisk(info_.points);  // every point may be kept: say so before reading
    std::vector<BinContents> bins;
    summary.source_passes = 1;
    if (assumed_) {
      clock.next();  // no pass of its own for the bounds: the binning pass takes them
      bins = binOnHeaderBox(summary);
    } else {
      firstPass();
      clock.next();
    }
    if (!binned_) {
      if (!decoded_) ++summary.source_passes;  // else pass 2 reads pass 1's decoded copy
      checkDisk(first_.bounds.count);
      fit_ = fitCube(first_.bounds, path_);
      chooseColouring(summary);
      bins = secondPass();
    }
    if (decoded_) summary.decoded_kept_bytes = decoded_->bytesWritten();
    decoded_.reset();  // its disk space, before the bins are voxelized
    clock.next();
    NodeResult root = voxelizeBins(bins);
    bins.clear();
    spillers_.clear();
    std::vector<EncodedLevel> levels;
    for (std::size_t i = 0; i < options_.depths.size(); ++i) {
      levels.push_back(flatten(root.levels[i], options_.depths[i]));
    }
    root = {};
    clock.next();
    summary.points_in_file = info_.points + info_.dropped_by_loader;
    summary.finite_points = first_.finite;
    summary.dropped_non_finite = points_read_ - first_.finite + info_.dropped_by_loader;
    summary.points_read = points_read_;
    summary.pieces_read = pieces_.size();
    summary.pieces = source_.pieceCount();
    summary.bytes_read = source_.bytesRead();
    summary.model_points = first_.bounds.count;
    summary.spilled_bytes = spilled_bytes_.load() + spill_->bytesWritten();
    summary.threads = threads_;
    PreparedModel model = assembleModel(std::move(levels), fit_, options_, path_, threads_);
    model.synthetic_colour = summary.shading == ScanShading::kNone && !options_.greyscale;
    clock.next();
    return model;
  }

 private:
  int finest() const { return options_.depths.back(); }

  void checkDisk(std::uint64_t points) const {
    const std::uint64_t in_memory = buffer_points_ * threads_;
    if (points <= in_memory) return;
    const std::uint64_t needed = (points - in_memory) * sizeof(BinnedPoint);
    const std::uint64_t free = freeDiskBytes(temp_dir_);
    if (free < needed) {
      throw PrepareError(path_ + ": " + std::to_string(points) + " points need about " +
                         std::to_string(needed >> 20) +
                         " MB of temporary disk beyond --memory, but " + temp_dir_.string() +
                         " has " + std::to_string(free >> 20) +
                         " MB free (use --temp-dir or a larger --memory)");
    }
  }

  // Reads every record once, in chunks spread over the threads: visit(chunk, first record, worker).
  // With a decoded copy, pass 1 fills it (before visit changes the points) and pass 2 reads it.
  template <typename Visit>
  void readAllPoints(const char* label, bool second_pass, Visit visit) {
    std::vector<PointChunk>& chunks = chunks_;  // kept for the next pass: already paged in
    chunks.resize(threads_);
    std::atomic<std::uint64_t> done{0};
    Progress progress(label, points_read_, "points");
    parallelFor(
        threads_, pieces_.size(),
        [&](std::size_t i, unsigned worker) {
          const std::size_t piece_index = pieces_[i];
          const PointRange piece = source_.piece(piece_index);
          if (decoded_ && second_pass) {
            decoded_->read(piece_index, chunks[worker]);
          } else {
            source_.read(piece.first, piece.count, chunks[worker]);
            if (decoded_) decoded_->keep(piece_index, chunks[worker]);
          }
          visit(chunks[worker], piece.first, worker);
          done += piece.count;
        },
        [&] { progress.update(done.load()); });
  }

  bool coarseIntensity() const {  // the first of the two intensity passes
    return !intensity_known_ && (info_.payload == PointPayload::kIntensity || info_.has_intensity);
  }

  // The workers' tallies merged into first_, and the pass's refusals.
  void mergeTallies(std::vector<PointTally>& workers) {
    for (std::size_t w = 1; w < workers.size(); ++w) workers[0].merge(workers[w]);
    first_ = std::move(workers[0]);
    if (pieces_.empty()) {  // not one piece met the crop box
      throw PrepareError(path_ + ": no point of the " + std::to_string(info_.points) +
                         " points lies inside the crop box (no COPC node's cube meets it)");
    }
    if (first_.finite == 0) {
      throw PrepareError(path_ + ": no finite points: all " + std::to_string(points_read_) +
                         " points have a NaN or infinite coordinate (every point)");
    }
    if (options_.crop && first_.bounds.count == 0) {
      throw PrepareError(path_ + ": no point of the " + std::to_string(first_.finite) +
                         " points lies inside the crop box");
    }
  }

  void firstPass() {
    std::vector<PointTally> workers(threads_);
    readAllPoints("pass 1 of 3, bounds", false,
                  [&](PointChunk& chunk, std::uint64_t first, unsigned worker) {
                    workers[worker].add(chunk, first, info_, filter_, coarseIntensity(), path_);
                  });
    mergeTallies(workers);
    first_.intensity.finishCoarse();
  }

  // The cube of the header's box, in the model's axes (the box's corners turned as the points
  // are); nullopt when it spans no volume (a header of zeros).
  std::optional<CubeFit> assumedFit() const {
    Bounds box;
    for (std::array<double, 3> corner : {info_.header_box->low, info_.header_box->high}) {
      filter_.keep(corner);  // no crop here: it only turns the axes
      box.add(corner);
    }
    try {
      return fitCube(box, path_);
    } catch (const PrepareError&) {
      return std::nullopt;
    }
  }

  // The one pass: bins every point on the header box's cube while tallying what pass 1 would
  // have; the bins when the cube from the points' own bounds, and the colouring, are what was
  // assumed (binned_), else nothing (the points are binned again on their own cube, from the
  // tally, so a box that lies costs a second reading, never a different model).
  std::vector<BinContents> binOnHeaderBox(PrepareSummary& summary) {
    using Payload = VoxelColouring::Payload;
    fit_ = *assumed_;
    // Assumed: the colours are not all 0 (else the intensity is shown, binned otherwise).
    const Payload assumed_payload =
        info_.payload == PointPayload::kRgb ? Payload::kRgb : Payload::kIntensity;
    colouring_.payload = assumed_payload;
    startBinning(points_read_);
    std::vector<PointTally> workers(threads_);
    const bool count_intensity = info_.payload == PointPayload::kIntensity || info_.has_intensity;
    for (PointTally& tally : workers) {
      if (count_intensity) tally.exact_intensity.start();
    }
    intensity_known_ = true;
    std::atomic<bool> marked{false};
    readAllPoints("pass 1 of 2, binning", false,
                  [&](PointChunk& chunk, std::uint64_t first, unsigned worker) {
                    const std::uint16_t brightest =
                        workers[worker].add(chunk, first, info_, filter_, coarseIntensity(), path_);
                    // Colours no channel of which passes 255 are binned as 8-bit, marked; once the
                    // file's choice is known, a marked colour is made what it would give.
                    const bool eight_bit = assumed_payload == Payload::kRgb && brightest <= 255;
                    if (eight_bit) marked = true;
                    binChunk(chunk, *spillers_[worker], eight_bit ? 0 : 8,
                             eight_bit ? kEightBitMark : 0, nullptr);
                  });
    mergeTallies(workers);
    const CubeFit fit = fitCube(first_.bounds, path_);
    chooseColouring(summary);
    if (sameFit(fit, *assumed_) && colouring_.payload == assumed_payload) {
      binned_ = true;
      marked_ = marked;
      return finishBinning();
    }
    summary.header_box_note = wrongBoxNote(fit);
    spillers_.clear();
    spilled_bytes_ += spill_->bytesWritten();
    spill_ = std::make_unique<SpillFile>(temp_dir_);  // the wrong bins' disk, given back
    return {};
  }

  // Why the header's box was not taken, for the summary.
  std::string wrongBoxNote(const CubeFit& fit) const {
    std::ostringstream note;
    note << "the header's box";
    if (!sameFit(fit, *assumed_)) {
      const Bounds& b = first_.bounds;
      note << " is not the points' (x " << cli::realText(b.low[0]) << " to "
           << cli::realText(b.high[0]) << ", y " << cli::realText(b.low[1]) << " to "
           << cli::realText(b.high[1]) << ", z " << cli::realText(b.low[2]) << " to "
           << cli::realText(b.high[2]) << " in the model's axes)";
    } else {
      note << " held, but every colour channel is 0";
    }
    note << ": binned again";
    return note.str();
  }

  // Decides what the voxels' colours come from, now that every colour has been seen once.
  void chooseColouring(PrepareSummary& summary) {
    using Payload = VoxelColouring::Payload;
    summary.shading = info_.shading;
    colouring_.payload = info_.payload == PointPayload::kRgb         ? Payload::kRgb
                         : info_.payload == PointPayload::kIntensity ? Payload::kIntensity
                                                                     : Payload::kNone;
    if (info_.colour_bits_detected) {
      if (first_.brightest_channel == 0) {  // colour fields, but no colour in them
        colouring_.payload = Payload::kIntensity;
        summary.shading = ScanShading::kIntensity;
        summary.colour_note = "every colour channel is 0, so the intensity is shown";
      } else if (first_.brightest_channel > 255) {
        colour_shift_ = 8;
        summary.colour_note = "16-bit colour";
      } else {
        summary.colour_note = "8-bit colour in 16-bit fields";
      }
    }
    if (colouring_.payload == Payload::kNone) {
      colouring_.near_z = voxelIndex(first_.bounds.low[2], fit_.origin[2], fit_.edge, finest());
      colouring_.far_z = voxelIndex(first_.bounds.high[2], fit_.origin[2], fit_.edge, finest());
    }
    if (intensity_known_) colouring_.intensity = first_.exact_intensity.range();
  }

  // Point i's payload: its colour, each channel shifted right by `shift` (8 for 16-bit colour),
  // with `mark`; or its intensity's bits.
  std::uint32_t payloadOf(const PointChunk& chunk, std::size_t i, int shift,
                          std::uint32_t mark) const {
    switch (colouring_.payload) {
      case VoxelColouring::Payload::kRgb: {
        const auto& c = chunk.rgb[i];
        return (std::uint32_t(c[0] >> shift & 0xffu) << 16 |
                std::uint32_t(c[1] >> shift & 0xffu) << 8 | (c[2] >> shift & 0xffu)) |
               mark;
      }
      case VoxelColouring::Payload::kIntensity:
        return std::bit_cast<std::uint32_t>(chunk.intensity[i]);
      case VoxelColouring::Payload::kNone:
        return 0;
    }
    return 0;
  }

  // A marked colour (binned as 8-bit before the file's choice was known) as the file's choice
  // makes it: the same 8-bit colour, or 0 for 16-bit colour (no channel of it passed 255).
  std::uint32_t unmarked(std::uint32_t payload) const {
    if (!(payload & kEightBitMark)) return payload;
    return colour_shift_ ? 0 : payload & ~kEightBitMark;
  }

  // Each thread's spiller, each buffer up to `points` (the budget's share at most): memory not
  // written is never touched, so only what the points fill counts, however unevenly the threads
  // share them.
  void startBinning(std::uint64_t points) {
    bin_level_ = std::min(kBinLevel, finest());
    const std::size_t bin_count = std::size_t{1} << (3 * bin_level_);
    const int bin_shift = 3 * (finest() - bin_level_);
    const std::uint64_t capacity = std::min<std::uint64_t>(buffer_points_, points);
    for (unsigned w = 0; w < threads_; ++w) {
      spillers_.push_back(std::make_unique<BinSpiller>(bin_shift, bin_count, capacity, *spill_));
    }
  }

  std::vector<BinContents> finishBinning() {
    std::vector<BinContents> bins(std::size_t{1} << (3 * bin_level_));
    parallelFor(threads_, spillers_.size(),
                [&](std::size_t i, unsigned) { spillers_[i]->groupTail(); });
    for (auto& spiller : spillers_) spiller->finish(true, bins);
    return bins;
  }

  // Bins the finite points of `chunk` that the filter keeps, on fit_; counts every finite
  // intensity into `intensity` when given.
  void binChunk(PointChunk& chunk, BinSpiller& spiller, int shift, std::uint32_t mark,
                IntensityPercentiles* intensity) const {
    const int depth = finest();
    const double cells = std::ldexp(1.0, depth);
    for (std::size_t i = 0; i < chunk.xyz.size(); ++i) {
      std::array<double, 3>& p = chunk.xyz[i];
      if (!isFinite(p)) continue;
      if (intensity) intensity->addFine(chunk.intensity[i]);
      if (!filter_.keep(p)) continue;
      const std::uint64_t key =
          mortonKey(voxelIndexIn(p[0], fit_.origin[0], fit_.edge, cells),
                    voxelIndexIn(p[1], fit_.origin[1], fit_.edge, cells),
                    voxelIndexIn(p[2], fit_.origin[2], fit_.edge, cells), depth);
      spiller.add(BinnedPoint::make(key, payloadOf(chunk, i, shift, mark)));
    }
  }

  std::vector<BinContents> secondPass() {
    startBinning(first_.bounds.count);
    const bool fine_intensity =
        colouring_.payload == VoxelColouring::Payload::kIntensity && !intensity_known_;
    std::vector<IntensityPercentiles> intensities;
    for (unsigned w = 0; fine_intensity && w < threads_; ++w) {
      intensities.push_back(first_.intensity.forFinePass());
    }
    readAllPoints("pass 2 of 3, binning", true,
                  [&](PointChunk& chunk, std::uint64_t, unsigned worker) {
                    binChunk(chunk, *spillers_[worker], colour_shift_, 0,
                             fine_intensity ? &intensities[worker] : nullptr);
                  });
    if (fine_intensity) {
      for (const IntensityPercentiles& partial : intensities) first_.intensity.merge(partial);
      colouring_.intensity = first_.intensity.range();
    }
    return finishBinning();
  }

  // The node of the bin at `level` with key `prefix`, from its points.
  NodeResult voxelizeBin(const BinContents& bin, int level, std::uint64_t prefix,
                         VoxelizerBuffers& buffers, ColourStore& store) {
    if (bin.count <= bin_points_) {
      const std::span<BinnedPoint> points = buffers.points.resize(bin.count);
      gatherBin(bin, points);
      if (marked_) {
        for (BinnedPoint& p : points) p.payload = unmarked(p.payload);
      }
      return voxelizeNode(points, level, colouring_, buffers, store);
    }
    buffers.points.resize(bin_points_);
    buffers.scratch.resize(bin_points_);
    if (level == finest()) {  // one voxel: just sum its points, a buffer at a time
      NodeResult node;
      node.levels.resize(options_.depths.size());
      forEachBlock(bin, buffers.points.span(), [&](std::span<const BinnedPoint> block) {
        for (const BinnedPoint& p : block) {
          node.sum.add(colouring_.pointColour(marked_ ? unmarked(p.payload) : p.payload));
        }
      });
      return node;
    }
    // Too many points for this thread's share: bin them again, some levels deeper, through a
    // temporary file of this thread's own, and voxelize the smaller bins one by one.
    const int child_level = std::min(level + kSubBinLevels, finest());
    const std::size_t child_count = std::size_t{1} << (3 * (child_level - level));
    SpillFile spill(temp_dir_);
    std::vector<BinContents> children(child_count);
    {
      BinSpiller spiller(3 * (finest() - child_level), child_count, buffers.points.span(), spill);
      forEachBlock(bin, buffers.scratch.span(), [&](std::span<const BinnedPoint> block) {
        for (const BinnedPoint& p : block) spiller.add(p);
      });
      spiller.finish(false, children);
    }
    std::vector<std::pair<std::uint64_t, NodeResult>> results;
    for (std::size_t c = 0; c < child_count; ++c) {
      if (children[c].count == 0) continue;
      const std::uint64_t child_prefix = prefix << (3 * (child_level - level)) | c;
      results.emplace_back(child_prefix,
                           voxelizeBin(children[c], child_level, child_prefix, buffers, store));
    }
    spilled_bytes_ += spill.bytesWritten();
    return combineNodes(level, child_level, std::move(results), colouring_, store);
  }

  NodeResult voxelizeBins(const std::vector<BinContents>& bins) {
    std::vector<std::size_t> occupied;
    for (std::size_t b = 0; b < bins.size(); ++b) {
      if (bins[b].count) occupied.push_back(b);
    }
    std::vector<std::pair<std::uint64_t, NodeResult>> results(occupied.size());
    // Each thread's buffers as large as the largest bin (up to its share of the budget) from the
    // start: grown bin by bin, they were fresh memory again and again.
    std::uint64_t largest = 0;
    for (std::size_t bin : occupied) largest = std::max(largest, bins[bin].count);
    std::vector<VoxelizerBuffers> buffers(threads_);
    for (VoxelizerBuffers& b : buffers) {
      b.points.resize(std::min(largest, bin_points_));
      b.scratch.resize(std::min(largest, bin_points_));
    }
    colour_stores_.resize(threads_);  // kept until the model is assembled
    std::atomic<std::uint64_t> done{0};
    Progress progress(binned_ ? "pass 2 of 2, voxelizing" : "pass 3 of 3, voxelizing",
                      first_.bounds.count, "points");
    parallelFor(
        threads_, occupied.size(),
        [&](std::size_t i, unsigned worker) {
          const std::size_t bin = occupied[i];
          results[i] = {bin, voxelizeBin(bins[bin], bin_level_, bin, buffers[worker],
                                         colour_stores_[worker])};
          done += bins[bin].count;
        },
        [&] { progress.update(done.load()); });
    buffers.clear();
    return combineNodes(0, bin_level_, std::move(results), colouring_, colour_stores_[0]);
  }

  static EncodedLevel flatten(SubtreePieces& pieces, int depth) {
    EncodedLevel level;
    level.depth = depth;
    std::size_t node_bytes = 0;
    for (const auto& piece : pieces.nodes) node_bytes += piece.size();
    level.nodes.reserve(node_bytes);
    adviseHugePages(level.nodes.data(), node_bytes);
    for (auto& piece : pieces.nodes) {
      level.nodes.insert(level.nodes.end(), piece.begin(), piece.end());
      piece = {};
    }
    for (const auto& piece : pieces.colours) level.leaves += piece.size();
    level.colours = std::move(pieces.colours);
    return level;
  }

  const PointSource& source_;
  const SourceInfo& info_;
  const std::string& path_;
  const PrepareOptions& options_;
  PointFilter filter_;
  unsigned threads_;
  fs::path temp_dir_;
  std::uint64_t buffer_points_ = 0;  // per thread, pass 2
  std::uint64_t bin_points_ = 0;     // per thread, voxelizing
  PointTally first_;                 // what the pass that takes the bounds learned
  CubeFit fit_;
  VoxelColouring colouring_;
  int colour_shift_ = 0;  // 8 for 16-bit colour channels
  int bin_level_ = 0;
  std::unique_ptr<SpillFile> spill_ = std::make_unique<SpillFile>(temp_dir_);
  std::optional<CubeFit> assumed_;  // the header box's cube, when the first pass bins on it
  bool binned_ = false;             // the first pass's bins are the model's (the box held)
  bool intensity_known_ = false;    // counted exactly in the first pass
  bool marked_ = false;  // some colours binned as 8-bit before the file's choice was known
  std::vector<std::unique_ptr<BinSpiller>> spillers_;
  std::vector<ColourStore> colour_stores_;  // per thread: the voxels' colours
  std::vector<PointChunk> chunks_;          // per thread: the records being read
  std::unique_ptr<DecodedPoints> decoded_;  // a compressed source's points, kept by pass 1
  std::vector<std::size_t> pieces_;         // the source's pieces the passes read
  std::uint64_t points_read_ = 0;           // their points
  std::atomic<std::uint64_t> spilled_bytes_{0};
};

}  // namespace

PreparedModel prepareFromSource(const PointSource& source, const std::string& path,
                                const PrepareOptions& options, const StreamOptions& stream,
                                PrepareSummary* summary) {
  if (options.outliers) {
    throw PrepareError(
        path + ": outlier removal needs the whole scan in memory, which is not available for " +
        source.info().format + " input");
  }
  const auto start = std::chrono::steady_clock::now();
  PrepareSummary local;
  const cli::FileSizeSignalIgnored
      file_size_signal;  // a spill past `ulimit -f`: an error, not a kill
  PreparedModel model = StreamedPreparer(source, path, options, stream).run(local);
  pruneModel(model, options, path);
  recordSampleReaches(model);
  local.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (summary) *summary = local;
  return model;
}

}  // namespace octopoint::prepare
