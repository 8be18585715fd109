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

// The points that go into the model, turned into its axes: finite (the caller checks), inside
// the crop box (compared in the scan's own axes, as cropScan does), y-up turned by 180 degrees
// about x.
class PointFilter {
 public:
  PointFilter(const std::optional<CropBox>& crop, ScanAxes axes, bool float_coordinates)
      : crop_(crop.has_value()), axes_(axes) {
    if (!crop) return;
    for (std::size_t axis = 0; axis < 3; ++axis) {  // float scans see the box as cropScan does
      low_[axis] = float_coordinates ? static_cast<float>(crop->low[axis]) : crop->low[axis];
      high_[axis] = float_coordinates ? static_cast<float>(crop->high[axis]) : crop->high[axis];
    }
  }

  bool keep(std::array<double, 3>& p) const {
    if (crop_) {
      for (std::size_t axis = 0; axis < 3; ++axis) {
        if (!(p[axis] >= low_[axis] && p[axis] <= high_[axis])) return false;
      }
    }
    if (axes_ == ScanAxes::kYUp) p = {p[0], -p[1], -p[2]};  // a rotation: no mirror image
    return true;
  }

 private:
  bool crop_;
  ScanAxes axes_;
  std::array<double, 3> low_{};
  std::array<double, 3> high_{};
};

bool isFinite(const std::array<double, 3>& p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

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

// What pass 1 learns, per worker and then merged.
struct FirstPass {
  Bounds bounds;
  IntensityPercentiles intensity;
  std::uint16_t brightest_channel = 0;  // the largest colour channel value in the file
  std::uint64_t finite = 0;

  void merge(const FirstPass& other) {
    bounds.merge(other.bounds);
    intensity.merge(other.intensity);
    brightest_channel = std::max(brightest_channel, other.brightest_channel);
    finite += other.finite;
  }
};

[[noreturn]] void failAbsurd(const std::string& path, const std::array<double, 3>& p,
                             std::size_t axis, double limit, std::uint64_t index) {
  std::ostringstream what;
  what << "absurd coordinate "
       << "xyz"[axis] << " = " << cli::realText(p[axis]) << ", beyond +-" << cli::realText(limit);
  throw PrepareError(path + ": " + what.str() + " (point " + std::to_string(index) + ")");
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
    // Room for the decoded copy and as much again for the bins' spills, else (also when no
    // temporary file can be made: a scan that fits the budget needs none) decode twice.
    if (info_.compressed && stream.decode_once && !pieces_.empty() &&
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
    firstPass();
    clock.next();
    checkDisk(first_.bounds.count);
    fit_ = fitCube(first_.bounds, path_);
    chooseColouring(summary);
    std::vector<BinContents> bins = secondPass();
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
    summary.spilled_bytes = spilled_bytes_.load() + spill_.bytesWritten();
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

  void firstPass() {
    std::vector<FirstPass> workers(threads_);
    const bool count_intensity = info_.payload == PointPayload::kIntensity || info_.has_intensity;
    readAllPoints("pass 1 of 3, bounds", false,
                  [&](PointChunk& chunk, std::uint64_t first, unsigned worker) {
                    FirstPass& state = workers[worker];
                    for (std::size_t i = 0; i < chunk.xyz.size(); ++i) {
                      std::array<double, 3>& p = chunk.xyz[i];
                      if (!isFinite(p)) continue;
                      for (std::size_t axis = 0; axis < 3; ++axis) {
                        if (std::fabs(p[axis]) > info_.coordinate_limit) {
                          failAbsurd(path_, p, axis, info_.coordinate_limit, first + i);
                        }
                      }
                      ++state.finite;
                      if (count_intensity) state.intensity.addCoarse(chunk.intensity[i]);
                      if (info_.colour_bits_detected) {
                        for (std::uint16_t channel : chunk.rgb[i]) {
                          state.brightest_channel = std::max(state.brightest_channel, channel);
                        }
                      }
                      if (filter_.keep(p)) state.bounds.add(p);
                    }
                  });
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
    first_.intensity.finishCoarse();
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
  }

  std::uint32_t payloadOf(const PointChunk& chunk, std::size_t i) const {
    switch (colouring_.payload) {
      case VoxelColouring::Payload::kRgb: {
        const auto& c = chunk.rgb[i];
        return std::uint32_t(c[0] >> colour_shift_ & 0xffu) << 16 |
               std::uint32_t(c[1] >> colour_shift_ & 0xffu) << 8 | (c[2] >> colour_shift_ & 0xffu);
      }
      case VoxelColouring::Payload::kIntensity:
        return std::bit_cast<std::uint32_t>(chunk.intensity[i]);
      case VoxelColouring::Payload::kNone:
        return 0;
    }
    return 0;
  }

  std::vector<BinContents> secondPass() {
    bin_level_ = std::min(kBinLevel, finest());
    const std::size_t bin_count = std::size_t{1} << (3 * bin_level_);
    const int bin_shift = 3 * (finest() - bin_level_);
    // Each thread's buffer can take every point (up to the budget): memory not written is never
    // touched, so only what the points fill counts, however unevenly the threads share them.
    const std::uint64_t capacity = std::min<std::uint64_t>(buffer_points_, first_.bounds.count);
    for (unsigned w = 0; w < threads_; ++w) {
      spillers_.push_back(std::make_unique<BinSpiller>(bin_shift, bin_count, capacity, spill_));
    }
    const bool fine_intensity = colouring_.payload == VoxelColouring::Payload::kIntensity;
    std::vector<IntensityPercentiles> intensities;
    for (unsigned w = 0; fine_intensity && w < threads_; ++w) {
      intensities.push_back(first_.intensity.forFinePass());
    }
    const int depth = finest();
    const double cells = std::ldexp(1.0, depth);
    readAllPoints("pass 2 of 3, binning", true,
                  [&](PointChunk& chunk, std::uint64_t, unsigned worker) {
                    BinSpiller& spiller = *spillers_[worker];
                    for (std::size_t i = 0; i < chunk.xyz.size(); ++i) {
                      std::array<double, 3>& p = chunk.xyz[i];
                      if (!isFinite(p)) continue;
                      if (fine_intensity) intensities[worker].addFine(chunk.intensity[i]);
                      if (!filter_.keep(p)) continue;
                      const std::uint64_t key =
                          mortonKey(voxelIndexIn(p[0], fit_.origin[0], fit_.edge, cells),
                                    voxelIndexIn(p[1], fit_.origin[1], fit_.edge, cells),
                                    voxelIndexIn(p[2], fit_.origin[2], fit_.edge, cells), depth);
                      spiller.add(BinnedPoint::make(key, payloadOf(chunk, i)));
                    }
                  });
    if (fine_intensity) {
      for (const IntensityPercentiles& partial : intensities) first_.intensity.merge(partial);
      colouring_.intensity = first_.intensity.range();
    }
    std::vector<BinContents> bins(bin_count);
    parallelFor(threads_, spillers_.size(),
                [&](std::size_t i, unsigned) { spillers_[i]->groupTail(); });
    for (auto& spiller : spillers_) spiller->finish(true, bins);
    return bins;
  }

  // The node of the bin at `level` with key `prefix`, from its points.
  NodeResult voxelizeBin(const BinContents& bin, int level, std::uint64_t prefix,
                         VoxelizerBuffers& buffers, ColourStore& store) {
    if (bin.count <= bin_points_) {
      const std::span<BinnedPoint> points = buffers.points.resize(bin.count);
      gatherBin(bin, points);
      return voxelizeNode(points, level, colouring_, buffers, store);
    }
    buffers.points.resize(bin_points_);
    buffers.scratch.resize(bin_points_);
    if (level == finest()) {  // one voxel: just sum its points, a buffer at a time
      NodeResult node;
      node.levels.resize(options_.depths.size());
      forEachBlock(bin, buffers.points.span(), [&](std::span<const BinnedPoint> block) {
        for (const BinnedPoint& p : block) node.sum.add(colouring_.pointColour(p.payload));
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
    Progress progress("pass 3 of 3, voxelizing", first_.bounds.count, "points");
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
  FirstPass first_;
  CubeFit fit_;
  VoxelColouring colouring_;
  int colour_shift_ = 0;  // 8 for 16-bit colour channels
  int bin_level_ = 0;
  SpillFile spill_{temp_dir_};
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
