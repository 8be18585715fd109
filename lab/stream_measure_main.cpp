// octopoint-stream-measure: how a chunked model streams over slow links (docs/streaming.md). For
// each view and each shaped link it starts octopoint-serve, streams the view, scores every frame
// against the scan's own reference render, and downloads the whole file first for comparison.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli/arguments.h"
#include "cli/error.h"
#include "cli/numbers.h"
#include "cli/real_numbers.h"
#include "cli/run_tool.h"
#include "codegen/cube_fit.h"
#include "codegen/prepare.h"
#include "lab/image_quality.h"
#include "lab/reference_render.h"
#include "lab/reference_surface.h"
#include "lab/stream_run.h"
#include "tools/chunked_render.h"
#include "tools/model_source.h"

namespace {

namespace fs = std::filesystem;
using namespace octopoint;

constexpr const char* kUsage =
    R"(usage: octopoint-stream-measure SCAN --model M.oct --serve OCTOPOINT-SERVE [options] )"
    R"(-o OUTDIR

Streams the chunked model M.oct (prepared from SCAN with --chunked) from octopoint-serve over
shaped links, one connection each, and records, per view and link: the time to the first picture,
the PSNR of every frame against the scan's surface reference (docs/tradeoff.md), )"
    R"(the time and bytes until the
frame is within 1 dB of the complete frame's PSNR, and the time to download the whole file first.
Writes OUTDIR/LABEL_runs.csv, LABEL_samples.csv, LABEL_psnr_bytes.png and LABEL_frames_VIEW.png.

  --axes y-down|y-up      the scan's axes, as given to octopoint-prepare (default y-down)
  --crop X0,Y0,Z0,X1,Y1,Z1  the crop box given to octopoint-prepare
  --size WxH              frame size (default 320x240)
  --view NAME:YAW:PITCH:ZOOM  a view (repeatable; default frontal:0:0:1 and zoom4:0:0:4)
  --link RATE:LATENCY     bytes per second and milliseconds (repeatable; default 5000:500,
                          50000:100 and 1000000:20)
  --fill                  draw every frame with hole filling (octopoint-render --fill), for files
                          holding depths finer than the scan samples densely (docs/streaming.md)
  --limit S               stop a run after S seconds (default 300); a whole-file download that
                          would take longer is computed from the link instead of measured
  --label NAME            prefix of the output files (default: the model's file name)
  -o, --output OUTDIR     where to write (created)
  -h, --help              show this help
)";

constexpr Rgb kBackground{236, 236, 240};

struct View {
  std::string name;
  Camera camera;
};

struct Options {
  std::string scan, model, serve, label;
  prepare::PrepareOptions prepare;
  Camera camera;
  std::vector<View> views;
  std::vector<Link> links;
  int limit_seconds = 300;
  bool fill = false;
  fs::path output = "out";
};

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, separator);) parts.push_back(part);
  return parts;
}

std::string linkName(std::uint64_t rate, std::uint32_t latency) {
  char text[64];
  if (rate >= 1'000'000)
    std::snprintf(text, sizeof text, "%.0f MB/s + %u ms", rate / 1e6, latency);
  else
    std::snprintf(text, sizeof text, "%.0f kB/s + %u ms", rate / 1e3, latency);
  return text;
}

Options parseOptions(int argc, char** argv) {
  Options options;
  cli::ArgumentReader args(argc, argv);
  while (args.next()) {
    if (args.is("-h") || args.is("--help")) {
      std::cout << kUsage;
      std::exit(0);
    } else if (args.is("--model")) {
      options.model = args.value();
    } else if (args.is("--serve")) {
      options.serve = args.value();
    } else if (args.is("--axes")) {
      options.prepare.axes = cli::parseChoice(args.name(), args.value(), {"y-down", "y-up"}) == 0
                                 ? prepare::ScanAxes::kYDown
                                 : prepare::ScanAxes::kYUp;
    } else if (args.is("--crop")) {
      options.prepare.crop = prepare::parseCropBox(args.name(), args.value());
    } else if (args.is("--size")) {
      const cli::FrameSize size =
          cli::parseFrameSize(args.name(), args.value(), 1, 4096, 4096 * 4096);
      options.camera.width = size.width;
      options.camera.height = size.height;
    } else if (args.is("--view")) {
      const std::vector<std::string> parts = split(args.value(), ':');
      if (parts.size() != 4) throw cli::Error("--view: expected NAME:YAW:PITCH:ZOOM");
      View view{parts[0], {}};
      view.camera.yaw = cli::parseDegrees(args.name(), parts[1]);
      view.camera.pitch = cli::parseDegrees(args.name(), parts[2]);
      view.camera.zoom = cli::parseZoom(args.name(), parts[3]);
      options.views.push_back(view);
    } else if (args.is("--link")) {
      const std::vector<std::string> parts = split(args.value(), ':');
      if (parts.size() != 2) throw cli::Error("--link: expected RATE:LATENCY");
      const auto rate = static_cast<std::uint64_t>(
          cli::parseInteger(args.name(), parts[0], 1, std::int64_t{1} << 40));
      const auto latency =
          static_cast<std::uint32_t>(cli::parseInt(args.name(), parts[1], 0, 600'000));
      options.links.push_back({linkName(rate, latency), rate, latency});
    } else if (args.is("--fill")) {
      options.fill = true;
    } else if (args.is("--limit")) {
      options.limit_seconds = cli::parseInt(args.name(), args.value(), 1, 86400);
    } else if (args.is("--label")) {
      options.label = args.value();
    } else if (args.is("-o") || args.is("--output")) {
      options.output = args.value();
    } else if (args.isPlain() && options.scan.empty()) {
      options.scan = args.current();
    } else {
      args.refuseUnknown();
    }
  }
  if (options.scan.empty() || options.model.empty() || options.serve.empty()) {
    throw cli::Error("give SCAN, --model and --serve (see --help)");
  }
  if (options.views.empty()) {
    options.views = {{"frontal", {}}, {"zoom4", {}}};
    options.views[1].camera.zoom = Q16::fromRaw(4 * Q16::kOneRaw);
  }
  for (View& view : options.views) {
    view.camera.width = options.camera.width;
    view.camera.height = options.camera.height;
  }
  if (options.links.empty()) {
    for (const auto& [rate, latency] :
         {std::pair<std::uint64_t, std::uint32_t>{5000, 500}, {50'000, 100}, {1'000'000, 20}}) {
      options.links.push_back({linkName(rate, latency), rate, latency});
    }
  }
  if (options.label.empty()) options.label = fs::path(options.model).stem().string();
  return options;
}

// The first sample within 1 dB of the complete frame's PSNR, or nullptr.
const StreamSample* withinOneDb(const StreamRunResult& run, double complete_psnr) {
  for (const StreamSample& sample : run.samples) {
    if (sample.psnr_db >= complete_psnr - 1.0) return &sample;
  }
  return nullptr;
}

// PSNR against bytes received, one curve per view (from the fastest link's run), log-scaled bytes.
cv::Mat plotPsnrAgainstBytes(const std::vector<std::pair<std::string, StreamRunResult>>& curves,
                             const std::vector<double>& complete_psnr, std::uint64_t file_bytes) {
  const int width = 900, height = 520, left = 70, right = 20, top = 30, bottom = 60;
  cv::Mat plot(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  double low = 1e9, high = 0;
  for (const auto& [name, run] : curves) {
    for (const StreamSample& s : run.samples) {
      low = std::min(low, s.psnr_db);
      high = std::max(high, s.psnr_db);
    }
  }
  low = std::floor(low - 1), high = std::ceil(high + 1);
  const double min_bytes = 1000, max_bytes = static_cast<double>(file_bytes) * 1.2;
  const auto x_of = [&](double bytes) {
    return left + static_cast<int>(
                      (std::log10(std::max(bytes, min_bytes)) - std::log10(min_bytes)) /
                      (std::log10(max_bytes) - std::log10(min_bytes)) * (width - left - right));
  };
  const auto y_of = [&](double psnr) {
    return top + static_cast<int>((high - psnr) / (high - low) * (height - top - bottom));
  };
  cv::rectangle(plot, {left, top}, {width - right, height - bottom}, cv::Scalar(0, 0, 0));
  for (double bytes = 1000; bytes <= max_bytes; bytes *= 10) {
    cv::line(plot, {x_of(bytes), height - bottom}, {x_of(bytes), height - bottom + 5},
             cv::Scalar(0, 0, 0));
    cv::putText(plot,
                bytes >= 1e6 ? std::to_string(static_cast<int>(bytes / 1e6)) + " MB"
                             : std::to_string(static_cast<int>(bytes / 1e3)) + " kB",
                {x_of(bytes) - 18, height - bottom + 22}, cv::FONT_HERSHEY_SIMPLEX, 0.45,
                cv::Scalar(0, 0, 0));
  }
  for (double psnr = low; psnr <= high; psnr += 2) {
    cv::putText(plot, std::to_string(static_cast<int>(psnr)), {left - 30, y_of(psnr) + 5},
                cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(0, 0, 0));
  }
  cv::line(plot, {x_of(static_cast<double>(file_bytes)), top},
           {x_of(static_cast<double>(file_bytes)), height - bottom}, cv::Scalar(160, 160, 160));
  cv::putText(plot, "bytes received (log); grey: whole file", {left + 200, height - 15},
              cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(0, 0, 0));
  cv::putText(plot, "PSNR dB", {5, top - 10}, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(0, 0, 0));
  const cv::Scalar colours[] = {{200, 60, 30}, {30, 140, 30}, {30, 30, 200}, {160, 30, 160}};
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const cv::Scalar colour = colours[c % 4];
    const StreamRunResult& run = curves[c].second;
    for (std::size_t i = 1; i < run.samples.size(); ++i) {
      const StreamSample& a = run.samples[i - 1];
      const StreamSample& b = run.samples[i];
      cv::line(plot, {x_of(static_cast<double>(a.bytes)), y_of(a.psnr_db)},
               {x_of(static_cast<double>(b.bytes)), y_of(a.psnr_db)}, colour, 2);
      cv::line(plot, {x_of(static_cast<double>(b.bytes)), y_of(a.psnr_db)},
               {x_of(static_cast<double>(b.bytes)), y_of(b.psnr_db)}, colour, 2);
    }
    cv::line(plot, {left, y_of(complete_psnr[c] - 1)}, {width - right, y_of(complete_psnr[c] - 1)},
             colour, 1, cv::LINE_4);
    cv::putText(plot, curves[c].first + " (thin: complete - 1 dB)",
                {left + 10, top + 20 + 20 * static_cast<int>(c)}, cv::FONT_HERSHEY_SIMPLEX, 0.5,
                colour, 1);
  }
  return plot;
}

// One stream of the model over one link, and the whole file's download time over it (measured
// when it fits the time limit, else from the link's latency and rate).
struct LinkRun {
  StreamRunResult result;
  double whole_seconds = 0;
  bool whole_measured = false;
};

// `strip` gets the frames at the bytes `figures` asks for.
LinkRun runOverLink(const Options& options, const Link& link, const View& view,
                    const cv::Mat& reference, std::uint64_t file_bytes, bool figures,
                    std::vector<cv::Mat>& strip) {
  const std::string folder = fs::absolute(fs::path(options.model)).parent_path().string();
  const std::string name = fs::path(options.model).filename().string();
  const std::vector<std::uint64_t> keep = {4096, 16384, 65536, 262144, 1048576};
  LinkRun run;
  ServeProcess server(options.serve, folder, link);
  const std::string url = "http://127.0.0.1:" + std::to_string(server.port()) + "/" + name;
  run.result = runStream(
      url, view.camera, options.fill, reference, std::chrono::seconds(options.limit_seconds),
      figures ? keep : std::vector<std::uint64_t>{},
      [&](std::uint64_t, const cv::Mat& frame) { strip.push_back(frame.clone()); });
  const double expected = link.latency_ms / 1000.0 + static_cast<double>(file_bytes) /
                                                         static_cast<double>(link.bytes_per_second);
  if (expected < options.limit_seconds) {
    run.whole_seconds =
        downloadWholeFile(url, file_bytes, std::chrono::seconds(options.limit_seconds));
    run.whole_measured = run.whole_seconds > 0;
  }
  if (!run.whole_measured) run.whole_seconds = expected;
  return run;
}

// The run's row of LABEL_runs.csv.
std::string runsRow(const Options& options, const View& view, const Link& link,
                    std::uint64_t file_bytes, const LinkRun& run, double complete_psnr) {
  const StreamRunResult& result = run.result;
  const StreamSample* good = withinOneDb(result, complete_psnr);
  char row[512];
  std::snprintf(
      row, sizeof row, "%s,%s,%s,%llu,%d,%d,%.3f,%.2f,%.3f,%llu,%.3f,%d,%.2f,%d,%.3f,%llu,%.4f\n",
      options.label.c_str(), view.name.c_str(), link.name.c_str(),
      static_cast<unsigned long long>(file_bytes), result.wanted_depth, result.deepest_level_depth,
      result.samples.empty() ? -1.0 : result.samples.front().seconds, complete_psnr,
      good ? good->seconds : -1.0, static_cast<unsigned long long>(good ? good->bytes : 0),
      run.whole_seconds, run.whole_measured ? 1 : 0, good ? run.whole_seconds / good->seconds : 0.0,
      result.complete ? 1 : 0, result.seconds, static_cast<unsigned long long>(result.bytes),
      static_cast<double>(result.bytes) / static_cast<double>(file_bytes));
  return row;
}

int run(int argc, char** argv) {
  const Options options = parseOptions(argc, argv);
  fs::create_directories(options.output);
  const std::unique_ptr<LoadedModel> whole = loadModel("", options.model, true);
  if (!whole->chunked)
    throw cli::Error(options.model + ": not a chunked model (prepare it with --chunked)");
  const std::uint64_t file_bytes = whole->file_bytes.size();
  const prepare::Scan scan = prepare::loadScan(options.scan);
  const prepare::Scan points = prepare::modelPoints(scan, options.scan, options.prepare);
  const prepare::CubeFit fit = prepare::fitCube(points.positions, options.scan);
  const tradeoff::ReferenceSurface surface = tradeoff::buildReferenceSurface(points);

  std::ofstream runs(options.output / (options.label + "_runs.csv"));
  runs << "model,view,link,file_bytes,depth,deepest_fetched,first_picture_s,complete_psnr_db,"
          "within_1db_s,"
          "within_1db_bytes,whole_file_s,whole_file_measured,speedup,complete,complete_s,complete_"
          "bytes,"
          "share_of_file\n";
  std::ofstream samples(options.output / (options.label + "_samples.csv"));
  samples << "model,view,link,seconds,bytes,psnr_db,held_chunks\n";
  std::vector<std::pair<std::string, StreamRunResult>> curves;
  std::vector<double> curve_complete;
  for (const View& view : options.views) {
    cv::Mat mask;
    const cv::Mat reference =
        tradeoff::renderReference(surface, fit, view.camera, kBackground, &mask);
    const cv::Mat complete_frame = renderChunkedView(*whole->chunked, view.camera, defaultVariant(),
                                                     options.fill, kBackground, nullptr);
    const double complete_psnr = tradeoff::psnr(reference, complete_frame);
    for (std::size_t l = 0; l < options.links.size(); ++l) {
      const Link& link = options.links[l];
      const bool figures = l + 1 == options.links.size();
      std::vector<cv::Mat> strip;
      const LinkRun run = runOverLink(options, link, view, reference, file_bytes, figures, strip);
      const StreamRunResult& result = run.result;
      const std::string row = runsRow(options, view, link, file_bytes, run, complete_psnr);
      runs << row;
      std::printf("%s", row.c_str());
      std::fflush(stdout);
      for (const StreamSample& s : result.samples) {
        samples << options.label << ',' << view.name << ',' << link.name << ',' << s.seconds << ','
                << s.bytes << ',' << s.psnr_db << ',' << s.held_chunks << '\n';
      }
      if (figures) {
        curves.emplace_back(view.name, result);
        curve_complete.push_back(complete_psnr);
        if (!result.final_frame.empty()) strip.push_back(result.final_frame);
        strip.push_back(reference);
        cv::Mat joined;
        cv::hconcat(strip, joined);
        cv::imwrite((options.output / (options.label + "_frames_" + view.name + ".png")).string(),
                    joined);
      }
    }
  }
  cv::imwrite((options.output / (options.label + "_psnr_bytes.png")).string(),
              plotPsnrAgainstBytes(curves, curve_complete, file_bytes));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return cli::runTool("octopoint-stream-measure", argc, argv, run);
}
