// The model's metric size (before: a u32 count of micrometres held 1 um .. 4.29 km and stored
// anything else wrong without a word). Version 2 stores picometres in a u64: every cube the
// preparer accepts (1 nm .. the 2,000 km that coordinates within +-10^6 m can span) is recorded to
// within 0.05%, through the `.oct` file and the generated sources alike; a smaller one is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "codegen/cube_fit.h"
#include "codegen/model_writer.h"
#include "codegen/prepare.h"
#include "codegen/prepare_error.h"
#include "octopoint/model.h"

namespace octopoint {
namespace {

// Three points spanning `span` scan units along x (and less along y and z).
prepare::Scan spanScan(float span) {
  prepare::Scan scan;
  scan.positions = {{0, 0, 0}, {span, span / 2, 0}, {span / 4, 0, span / 3}};
  scan.points_in_file = 3;
  return scan;
}

// The cube edge a model of `scan` records, read back from its `.oct` image.
std::uint64_t recordedPicometres(const prepare::Scan& scan, double metres_per_unit) {
  prepare::PrepareOptions options;
  options.name = "span";
  options.depths = {2};
  options.metres_per_scan_unit = metres_per_unit;
  const std::vector<std::uint8_t> image =
      prepare::serializeModel(prepare::prepareModel(scan, "span.pcd", options));
  ModelIssue issue;
  const std::optional<ModelView> model = ModelView::fromBytes(image, &issue);
  EXPECT_TRUE(model.has_value()) << describe(issue.error);
  return model ? model->cubeEdgePicometres() : 0;
}

TEST(MetricSize, ScansBeyondVersionOnesLimitsAreRecordedExactly) {
  // 5 km and 2,000 km (the loader's coordinate limit, +-10^6, in metres), exact in float.
  EXPECT_EQ(recordedPicometres(spanScan(5000.0f), 1.0), 5'000'000'000'000'000u);
  EXPECT_EQ(recordedPicometres(spanScan(2.0e6f), 1.0), 2'000'000'000'000'000'000u);
  EXPECT_EQ(recordedPicometres(spanScan(500000.0f), 0.01), 5'000'000'000'000'000u);  // 5 km in cm
  EXPECT_EQ(recordedPicometres(spanScan(70.0f), 0.001), 70'000'000'000u);            // 7 cm in mm
}

TEST(MetricSize, ScansBelowAMicrometreAreRecordedToWithinRounding) {
  for (const float metres : {5e-7f, 3.3e-8f, 1.5e-9f}) {
    const double exact_pm = static_cast<double>(metres) * 1e12;
    const auto recorded = static_cast<double>(recordedPicometres(spanScan(metres), 1.0));
    EXPECT_LE(std::fabs(recorded - exact_pm), 0.5) << metres << " m";
    EXPECT_LE(std::fabs(recorded - exact_pm) / exact_pm, 5e-4) << metres << " m";
  }
}

TEST(MetricSize, ACubeBelowOneNanometreIsRefusedByName) {
  for (const float metres : {9e-10f, 1e-12f, 1e-30f}) {
    try {
      recordedPicometres(spanScan(metres), 1.0);
      ADD_FAILURE() << metres << " m was accepted";
    } catch (const prepare::PrepareError& error) {
      EXPECT_NE(std::string(error.what()).find("span.pcd: the scan spans"), std::string::npos)
          << error.what();
      EXPECT_NE(std::string(error.what()).find("from 1 nm"), std::string::npos) << error.what();
    }
  }
}

TEST(MetricSize, TheGeneratedSourcesRecordThePicometresToo) {
  prepare::PrepareOptions options;
  options.name = "far";
  options.depths = {2};
  const std::vector<prepare::OutputFile> files =
      prepare::emitSources(prepare::prepareModel(spanScan(5000.0f), "far.pcd", options));
  ASSERT_GE(files.size(), 2u);
  // Version 6, flags 2 (the scan has no colour: its palette is a made-up shade), 5 km.
  EXPECT_NE(files[1].contents.find("\"far\", 6, 2, 5000000000000000u,"), std::string::npos)
      << files[1].contents;
}

}  // namespace
}  // namespace octopoint
