#include "lab/tradeoff_report.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <sstream>

namespace octopoint::tradeoff {
namespace {

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

// "1" (one pixel per leaf), "3" (3 x 3) or "3x2" (columns x rows).
std::string splatSize(const SweepResult& r) {
  if (r.splat_columns == r.splat_rows) return std::to_string(r.splat_columns);
  return std::to_string(r.splat_columns) + "x" + std::to_string(r.splat_rows);
}

std::string cellName(const SweepCell& cell) {
  char text[64];
  std::snprintf(text, sizeof text, "%dx%d zoom %g", cell.width, cell.height, cell.zoom);
  return text;
}

// "a / b / c" of one measure over before, before + fill and after ("-" where absent).
std::string triple(const SweepCell& cell,
                   const std::function<std::string(const SweepResult&)>& show) {
  std::string text;
  for (Config config : {Config::kBefore, Config::kBeforeFilled, Config::kAfter}) {
    const SweepResult* r = cell.find(config);
    text += (text.empty() ? "" : " / ") + (r ? show(*r) : std::string("-"));
  }
  return text;
}

const SweepCell* findCell(const std::vector<SweepCell>& cells, int width, int height, double zoom) {
  for (const SweepCell& cell : cells) {
    if (cell.width == width && cell.height == height && cell.zoom == zoom) return &cell;
  }
  return nullptr;
}

// One target: its statement, whether it holds, and the numbers behind the verdict.
struct Verdict {
  explicit Verdict(std::string text) : statement(std::move(text)) {}
  std::string statement;
  bool checked = false;  // false: the sweep lacks the cells it needs
  bool met = false;
  std::string numbers;
};

// The empty share of the silhouette, after, at every size and zoom.
Verdict emptyShareVerdict(const std::vector<SweepCell>& cells) {
  Verdict v{"Empty share of the silhouette <= 1% at every size and zoom (after)"};
  double worst = -1, worst_interior = -1;
  std::string where, interior_where, over;
  for (const SweepCell& cell : cells) {
    const SweepResult* after = cell.find(Config::kAfter);
    if (!after) continue;
    if (after->quality.empty_share > worst)
      worst = after->quality.empty_share, where = cellName(cell);
    if (after->quality.interior_empty_share > worst_interior)
      worst_interior = after->quality.interior_empty_share, interior_where = cellName(cell);
    if (after->quality.empty_share > 0.01) over += (over.empty() ? "" : ", ") + cellName(cell);
  }
  v.checked = worst >= 0;
  v.met = v.checked && over.empty();
  v.numbers = "worst " + format("%.2f%%", 100 * worst) + " (" + where + ")" +
              (over.empty() ? "" : "; above 1%: " + over) + "; in the interior (" +
              std::to_string(kBandWidth) + " pixels in from the outline) worst " +
              format("%.2f%%", 100 * worst_interior) + " (" + interior_where + ")";
  return v;
}

// The PSNR targets at 640x480 and larger: the gain over today's renderer with filling, and the
// drop from 320x240 zoom 1. Appends both verdicts.
void addPsnrVerdicts(const std::vector<SweepCell>& cells, std::vector<Verdict>& verdicts) {
  const SweepCell* base = findCell(cells, 320, 240, 1);
  const SweepResult* base_after = base ? base->find(Config::kAfter) : nullptr;
  Verdict gain{"PSNR at 640x480 and larger >= today's renderer with filling + 6 dB"};
  Verdict drop{"PSNR at 640x480 and larger >= the 320x240 zoom 1 figure - 3 dB"};
  double least_gain = 1e9, least_psnr = 1e9;
  std::string gain_at, psnr_at, gain_fail, drop_fail, above_ceiling, above_cover;
  for (const SweepCell& cell : cells) {
    const SweepResult* after = cell.find(Config::kAfter);
    const SweepResult* filled = cell.find(Config::kBeforeFilled);
    if (!after || !filled || std::int64_t{cell.width} * cell.height < 640 * 480) continue;
    const double delta = after->quality.psnr - filled->quality.psnr;
    if (delta < least_gain) least_gain = delta, gain_at = cellName(cell);
    if (delta < 6)
      gain_fail += (gain_fail.empty() ? "" : ", ") + cellName(cell) + format(" (%+.1f dB)", delta);
    if (filled->quality.psnr + 6 > after->voxel_cover_psnr) {
      above_cover += (above_cover.empty() ? "" : ", ") + cellName(cell) +
                     format(" (%.1f", filled->quality.psnr + 6) +
                     format(" > %.1f dB)", after->voxel_cover_psnr);
    }
    if (filled->quality.psnr + 6 > after->palette_ceiling_psnr) {
      above_ceiling += (above_ceiling.empty() ? "" : ", ") + cellName(cell) +
                       format(" (%.1f", filled->quality.psnr + 6) +
                       format(" > %.1f dB)", after->palette_ceiling_psnr);
    }
    if (after->quality.psnr < least_psnr)
      least_psnr = after->quality.psnr, psnr_at = cellName(cell);
    if (base_after && after->quality.psnr < base_after->quality.psnr - 3) {
      drop_fail += (drop_fail.empty() ? "" : ", ") + cellName(cell) +
                   format(" (%.1f dB)", after->quality.psnr);
    }
  }
  gain.checked = least_gain < 1e9;
  gain.met = gain.checked && gain_fail.empty();
  gain.numbers = "least gain " + format("%+.1f dB", least_gain) + " (" + gain_at + ")" +
                 (gain_fail.empty() ? "" : "; under +6 dB: " + gain_fail) +
                 "; filled + 6 dB above the after model's palette ceiling (no frame of it can "
                 "reach it): " +
                 (above_ceiling.empty() ? std::string("none") : above_ceiling) +
                 "; filled + 6 dB above the exact cover of the after model's finest voxels (each "
                 "covering exactly the pixel centres inside its projection): " +
                 (above_cover.empty() ? std::string("none") : above_cover);
  drop.checked = gain.checked && base_after;
  drop.met = drop.checked && drop_fail.empty();
  if (drop.checked) {
    drop.numbers = "320x240 zoom 1: " + format("%.1f dB", base_after->quality.psnr) + ", lowest " +
                   format("%.1f dB", least_psnr) + " (" + psnr_at + ")" +
                   (drop_fail.empty() ? "" : "; below: " + drop_fail);
  }
  verdicts.push_back(gain);
  verdicts.push_back(drop);
}

// Zoom 0.25's time against zoom 1's, per size, after.
Verdict zoomCostVerdict(const std::vector<SweepCell>& cells) {
  Verdict v{"Zoom 0.25 costs at most 1/4 of zoom 1 (same size, after)"};
  double worst = -1;
  std::string list;
  bool all = true;
  for (const SweepCell& cell : cells) {
    if (cell.zoom != 1) continue;
    const SweepCell* quarter = findCell(cells, cell.width, cell.height, 0.25);
    const SweepResult* a = cell.find(Config::kAfter);
    const SweepResult* q = quarter ? quarter->find(Config::kAfter) : nullptr;
    if (!a || !q) continue;
    const double ratio = q->ms_per_frame / a->ms_per_frame;
    worst = std::max(worst, ratio);
    all = all && ratio <= 0.25;
    list += (list.empty() ? "" : ", ") + std::to_string(cell.width) + "x" +
            std::to_string(cell.height) + format(" %.2f", ratio);
  }
  v.checked = worst >= 0;
  v.met = v.checked && all;
  v.numbers = "ratio per size: " + list;
  return v;
}

// 1920x1080's time against 320x240's, per zoom, after.
Verdict sizeCostVerdict(const std::vector<SweepCell>& cells) {
  Verdict v{"A 1920x1080 frame costs at most 27x a 320x240 one (same zoom, after)"};
  double worst = -1;
  std::string list;
  for (const SweepCell& cell : cells) {
    if (cell.width != 1920 || cell.height != 1080) continue;
    const SweepCell* small = findCell(cells, 320, 240, cell.zoom);
    const SweepResult* big = cell.find(Config::kAfter);
    const SweepResult* s = small ? small->find(Config::kAfter) : nullptr;
    if (!big || !s) continue;
    const double ratio = big->ms_per_frame / s->ms_per_frame;
    worst = std::max(worst, ratio);
    list += (list.empty() ? "" : ", ") + format("zoom %g", cell.zoom) + format(" %.1fx", ratio);
  }
  v.checked = worst >= 0;
  v.met = v.checked && worst <= 27;
  v.numbers = "ratio per zoom: " + list;
  return v;
}

// Depth auto without filling against today's renderer with filling, in time and PSNR.
Verdict autoDepthVerdict(const std::vector<SweepCell>& cells) {
  Verdict v{
      "Depth auto without filling beats today's renderer with filling in time and PSNR (every "
      "cell)"};
  int compared = 0;
  std::string slower, worse;
  for (const SweepCell& cell : cells) {
    const SweepResult* after = cell.find(Config::kAfter);
    const SweepResult* filled = cell.find(Config::kBeforeFilled);
    if (!after || !filled) continue;
    ++compared;
    if (after->ms_per_frame >= filled->ms_per_frame) {
      slower += (slower.empty() ? "" : ", ") + cellName(cell) +
                format(" (%.3f", after->ms_per_frame) +
                format(" vs %.3f ms)", filled->ms_per_frame);
    }
    if (after->quality.psnr <= filled->quality.psnr)
      worse += (worse.empty() ? "" : ", ") + cellName(cell);
  }
  v.checked = compared > 0;
  v.met = v.checked && slower.empty() && worse.empty();
  v.numbers = std::to_string(compared) + " cells compared" +
              (slower.empty() ? "" : "; not faster: " + slower) +
              (worse.empty() ? "" : "; not better PSNR: " + worse);
  return v;
}

std::vector<Verdict> checkTargets(const std::vector<SweepCell>& cells) {
  std::vector<Verdict> verdicts;
  verdicts.push_back(emptyShareVerdict(cells));
  addPsnrVerdicts(cells, verdicts);
  verdicts.push_back(zoomCostVerdict(cells));
  verdicts.push_back(sizeCostVerdict(cells));
  verdicts.push_back(autoDepthVerdict(cells));
  return verdicts;
}

// Per cell: each model's palette ceiling and exact voxel cover against the filled before frame
// and the after frame, and where those two frames' squared error lies (lab/error_regions.h).
std::string ceilingTable(const std::vector<SweepCell>& cells) {
  std::ostringstream md;
  md << "Palette ceiling (the reference in the model's palette colours and the background: no "
        "frame of that model scores more), exact voxel cover (the model's finest voxels, each "
        "covering exactly the pixel centres inside its projection: lab/voxel_cover.h) and where "
        "each frame's squared error lies, by region of the reference's silhouette: its interior, "
        "the "
     << kBandWidth << "-pixel bands inside and outside its outline, the rest:\n\n"
     << "| size | zoom | palette ceiling dB | exact voxel cover dB | PSNR dB | squared error: "
        "interior / inner band / outer band / rest | interior MSE |\n"
     << "|---|---|---|---|---|---|---|\n";
  // "a / b" of one measure over before + fill and after.
  auto pair = [](const SweepCell& cell,
                 const std::function<std::string(const SweepResult&)>& show) {
    const SweepResult* filled = cell.find(Config::kBeforeFilled);
    const SweepResult* after = cell.find(Config::kAfter);
    return (filled ? show(*filled) : "-") + " / " + (after ? show(*after) : "-");
  };
  auto shares = [](const SweepResult& r) {
    std::string text;
    for (int region = 0; region < kRegionCount; ++region) {
      text += (text.empty() ? "" : ", ") +
              format("%.0f%%", 100 * r.quality.error_by_region.share(Region(region)));
    }
    return text;
  };
  for (const SweepCell& cell : cells) {
    md << "| " << cell.width << "x" << cell.height << " | " << format("%g", cell.zoom) << " | "
       << pair(cell, [](const SweepResult& r) { return format("%.1f", r.palette_ceiling_psnr); })
       << " | "
       << pair(cell, [](const SweepResult& r) { return format("%.2f", r.voxel_cover_psnr); })
       << " | " << pair(cell, [](const SweepResult& r) { return format("%.2f", r.quality.psnr); })
       << " | " << pair(cell, shares) << " | "
       << pair(cell,
               [](const SweepResult& r) {
                 return format("%.0f", r.quality.error_by_region.mse(Region::kInterior));
               })
       << " |\n";
  }
  md << "\nEach cell: before with hole filling (the before model's ceiling) / after.\n";
  return md.str();
}

// Box against smooth splats (both depth auto) against the exact cover of the finest voxels, with
// the smooth-splat target: at zoom 2 and beyond, smooth >= cover + 3 dB and its SSIM higher.
std::string splatsTable(const std::vector<SweepCell>& cells) {
  std::ostringstream md;
  std::string missed;
  int checked = 0;
  md << "\nBox and smooth splats (`--splats`, docs/splats.md), both at depth auto, against the "
        "exact cover of the finest voxels (each covering exactly the pixel centres inside its "
        "projection), all three measured against the reference:\n\n"
     << "| size | zoom | depth | ms per frame box / smooth | PSNR dB box / smooth / cover | "
        "smooth - cover dB | SSIM box / smooth / cover |\n"
     << "|---|---|---|---|---|---|---|\n";
  for (const SweepCell& cell : cells) {
    const SweepResult* box = cell.find(Config::kAfter);
    const SweepResult* smooth = cell.find(Config::kAfterSmooth);
    if (!box || !smooth) continue;
    auto ms = [](double value) { return format(value < 1 ? "%.3f" : "%.2f", value); };
    const double gain = smooth->quality.psnr - smooth->voxel_cover_psnr;
    md << "| " << cell.width << "x" << cell.height << " | " << format("%g", cell.zoom) << " | "
       << smooth->depth << " | " << ms(box->ms_per_frame) << " / " << ms(smooth->ms_per_frame)
       << " | " << format("%.2f", box->quality.psnr) << " / "
       << format("%.2f", smooth->quality.psnr) << " / " << format("%.2f", smooth->voxel_cover_psnr)
       << " | " << format("%+.2f", gain) << " | " << format("%.3f", box->quality.ssim) << " / "
       << format("%.3f", smooth->quality.ssim) << " / " << format("%.3f", smooth->voxel_cover_ssim)
       << " |\n";
    if (cell.zoom < 2) continue;
    ++checked;
    if (gain < 3 || smooth->quality.ssim <= smooth->voxel_cover_ssim)
      missed += (missed.empty() ? "" : ", ") + cellName(cell);
  }
  if (checked == 0) return "";
  md << "\nSmooth at zoom 2 and beyond, PSNR >= exact voxel cover + 3 dB and SSIM higher, in "
        "every cell: "
     << (missed.empty() ? "**met**" : "**missed** in " + missed) << "\n";
  return md.str();
}

}  // namespace

const char* configName(Config config) {
  switch (config) {
    case Config::kBefore:
      return "before";
    case Config::kBeforeFilled:
      return "before_fill";
    case Config::kAfter:
      return "after";
    case Config::kAfterSmooth:
      return "after_smooth";
  }
  return "?";
}

const SweepResult* SweepCell::find(Config config) const {
  for (const SweepResult& r : results) {
    if (r.config == config) return &r;
  }
  return nullptr;
}

std::string sweepCsv(const std::string& label, const std::vector<SweepCell>& cells) {
  std::string csv =
      "scan,width,height,zoom,config,depth,splat_columns,splat_rows,ms_per_frame,empty_share,"
      "interior_empty_share,psnr_db,ssim,palette_ceiling_psnr_db";
  for (int region = 0; region < kRegionCount; ++region)
    csv += std::string(",sse_share_") + regionName(Region(region));
  csv += ",voxel_cover_psnr_db,voxel_cover_ssim\n";
  for (const SweepCell& cell : cells) {
    for (const SweepResult& r : cell.results) {
      const RegionError& error = r.quality.error_by_region;
      char line[384];
      std::snprintf(
          line, sizeof line,
          "%s,%d,%d,%g,%s,%d,%d,%d,%.4f,%.5f,%.5f,%.3f,%.4f,%.3f,%.4f,%.4f,%.4f,%.4f,%.3f,%.4f\n",
          label.c_str(), cell.width, cell.height, cell.zoom, configName(r.config), r.depth,
          r.splat_columns, r.splat_rows, r.ms_per_frame, r.quality.empty_share,
          r.quality.interior_empty_share, r.quality.psnr, r.quality.ssim, r.palette_ceiling_psnr,
          error.share(Region::kInterior), error.share(Region::kInnerBand),
          error.share(Region::kOuterBand), error.share(Region::kRest), r.voxel_cover_psnr,
          r.voxel_cover_ssim);
      csv += line;
    }
  }
  return csv;
}

std::string sweepMarkdown(const std::string& label, const std::string& models,
                          const std::vector<SweepCell>& cells) {
  std::ostringstream md;
  md << "### " << label << "\n\n"
     << models << "\n\n"
     << "Each cell: before (finest depth, one pixel per voxel) / before with hole filling / after "
        "(depth auto, "
        "splats, no filling).\n\n"
     << "| size | zoom | depth drawn | splat px | ms per frame | empty share of silhouette | PSNR "
        "dB | SSIM |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  for (const SweepCell& cell : cells) {
    md << "| " << cell.width << "x" << cell.height << " | " << format("%g", cell.zoom) << " | "
       << triple(cell, [](const SweepResult& r) { return std::to_string(r.depth); }) << " | "
       << triple(cell, splatSize) << " | "
       << triple(cell,
                 [](const SweepResult& r) {
                   return format(r.ms_per_frame < 1 ? "%.3f" : "%.2f", r.ms_per_frame);
                 })
       << " | "
       << triple(cell,
                 [](const SweepResult& r) { return format("%.1f%%", 100 * r.quality.empty_share); })
       << " | " << triple(cell, [](const SweepResult& r) { return format("%.1f", r.quality.psnr); })
       << " | " << triple(cell, [](const SweepResult& r) { return format("%.2f", r.quality.ssim); })
       << " |\n";
  }
  md << "\n" << ceilingTable(cells) << splatsTable(cells);
  md << "\nTargets, from the numbers above:\n\n";
  for (const Verdict& v : checkTargets(cells)) {
    md << "- " << v.statement << ": "
       << (v.checked ? (v.met ? "**met**" : "**missed**") + std::string(", ") + v.numbers
                     : std::string("not in this sweep"))
       << "\n";
  }
  return md.str();
}

}  // namespace octopoint::tradeoff
