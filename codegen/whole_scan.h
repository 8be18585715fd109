#pragma once
// Scans the preparer does not stream: those PCL reads whole (ascii or compressed PCD/PLY, layouts
// the streamed readers do not take) and any scan whose options look at each point's neighbours
// (outlier removal, normal estimation).
//
// octopoint-prepare itself links no PCL: loading PCL, VTK and their 70 libraries took the dynamic
// loader about 0.2 s of CPU at every start, a tenth of preparing 10^7 points. For these scans it
// runs, in its place (exec, same arguments, same process), octopoint-prepare-pcl from its own
// directory: the same program linked with PCL, whose prepareWholeScan does the work.

#include <string>

#include "codegen/prepare.h"
#include "codegen/prepared_model.h"
#include "codegen/streamed_prepare.h"

namespace octopoint::prepare {

// The model from a scan read whole, filling `summary`'s counts. `argv` is the program's own
// (null-terminated), for the hand-over; throws PrepareError with one line on any failure.
PreparedModel prepareWholeScan(const std::string& scan_path, const PrepareOptions& options,
                               const StreamOptions& stream, PrepareSummary& summary, char** argv);

// The name of the program that links PCL, beside octopoint-prepare.
inline constexpr const char* kWholeScanProgram = "octopoint-prepare-pcl";

}  // namespace octopoint::prepare
