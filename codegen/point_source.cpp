// Choosing how a scan file is read (codegen/point_source.h), and serving in-memory scans.

#include "codegen/point_source.h"

#include <algorithm>
#include <cctype>
#include <system_error>

#include "cli/error.h"
#include "cli/input_file.h"
#include "codegen/binary_scan_source.h"
#include "codegen/las_reader.h"
#include "codegen/prepare_error.h"
#include "codegen/scan_header_check.h"

namespace octopoint::prepare {
namespace {

namespace fs = std::filesystem;

class MemorySource : public PointSource {
 public:
  explicit MemorySource(const Scan& scan, std::string format = "in memory") : scan_(scan) {
    info_.points = scan.positions.size();
    info_.payload = scan.colours.empty() ? PointPayload::kNone : PointPayload::kRgb;
    info_.shading = scan.shading;
    info_.dropped_by_loader = scan.dropped_non_finite;
    info_.organized = scan.organized;
    info_.streamed = false;
    info_.format = std::move(format);
  }

  const SourceInfo& info() const override { return info_; }

  void read(std::uint64_t first, std::size_t count, PointChunk& chunk) const override {
    chunk.resize(count, info_);
    for (std::size_t i = 0; i < count; ++i) {
      const auto& p = scan_.positions[first + i];
      chunk.xyz[i] = {p[0], p[1], p[2]};
      if (!scan_.colours.empty()) {
        const auto& c = scan_.colours[first + i];
        chunk.rgb[i] = {c[0], c[1], c[2]};
      }
    }
  }

 private:
  const Scan& scan_;
  SourceInfo info_;
};

// A scan PCL has loaded, owned by its source.
class LoadedScanSource final : public PointSource {
 public:
  LoadedScanSource(Scan scan, const char* format)
      : scan_(std::move(scan)), memory_(scan_, format) {}
  const SourceInfo& info() const override { return memory_.info(); }
  void read(std::uint64_t first, std::size_t count, PointChunk& chunk) const override {
    memory_.read(first, count, chunk);
  }

 private:
  Scan scan_;
  MemorySource memory_;  // after scan_, which it reads
};

std::string lowerExtension(const fs::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

// The one input-file check (cli/input_file.h), in the loader's "PATH: what (where)" form.
std::uint64_t checkScanFile(const fs::path& path) {
  std::uint64_t size = 0;
  try {
    size = cli::checkInputFile(path, kStreamedScanInput);
  } catch (const cli::Error& error) {
    throw PrepareError(std::string(error.what()) + " (opening the scan)");
  }
  if (size == 0) fail(path, "empty file (0 bytes)", "opening the scan");
  return size;
}

}  // namespace

std::unique_ptr<PointSource> memorySource(const Scan& scan) {
  return std::make_unique<MemorySource>(scan);
}

std::unique_ptr<PointSource> openStreamedSource(const fs::path& path) {
  // What the path is (a FIFO, a directory, too large) before what it is called, as loadScan does.
  const std::uint64_t size = checkScanFile(path);
  const std::string extension = lowerExtension(path);
  const bool is_las = extension == ".las" || extension == ".laz";
  const bool is_ply = extension == ".ply";
  if (!is_las && !is_ply && extension != ".pcd") {
    fail(path, "unknown extension '" + printable(extension) + "', expected .las, .pcd or .ply",
         "file name");
  }
  if (is_las) return openLasSource(path);
  is_ply ? checkPlyHeader(path, size) : checkPcdHeader(path, size);
  return openBinaryScanSource(path, size, is_ply);
}

std::unique_ptr<PointSource> loadedScanSource(Scan scan, const fs::path& path) {
  return std::make_unique<LoadedScanSource>(
      std::move(scan), lowerExtension(path) == ".ply" ? "PLY through PCL" : "PCD through PCL");
}

}  // namespace octopoint::prepare
