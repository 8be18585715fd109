#pragma once
// Checks of a scan's point layout made from its header, before PCL reads a byte of the body: a
// layout we would refuse after reading (x stored as uint8) is refused before PCL spends seconds
// and gigabytes on a large body, and layouts that PCL 1.13 aborts on or rejects without saying
// why (a list property among the vertex's, a property name given twice) get a message that says
// what and where.

#include <filesystem>
#include <string>

#include "codegen/ascii_body.h"

namespace octopoint::prepare {

// Throws PrepareError for a scan without `axis` (x, y or z) as one float32 value, naming the
// fields it has (`field_list`, printable): what the header check and loadScan, after PCL read the
// file, both say.
[[noreturn]] void failWithoutFloatAxis(const std::filesystem::path& path, const char* axis,
                                       const std::string& field_list);

// Fails unless `point` holds x, y and z each as one float32 (the first field of each name, the
// one PCL's findField takes), with the message loadScan gives after reading.
void requireFloatXyz(const std::filesystem::path& path, const AsciiElement& point);

// Fails on a property name given twice in a PLY element, and on a list among the vertex's.
void checkPlyProperties(const std::filesystem::path& path, const AsciiElement& element);

}  // namespace octopoint::prepare
