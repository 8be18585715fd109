#pragma once
// Statistical outlier removal for range scans (PrepareOptions::outliers): real Kinect scans have
// far-away junk points that would otherwise stretch the fitted cube and squash the model.

#include <string>

#include "codegen/prepare.h"
#include "codegen/scan_loader.h"

namespace octopoint::prepare {

// The points of `scan` that are not outliers by `rule`, with their colours. Throws PrepareError
// naming `scan_path` when fewer than rule.neighbours + 1 points are given or none is left.
Scan removeOutliers(const Scan& scan, const OutlierRemoval& rule, const std::string& scan_path);

}  // namespace octopoint::prepare
