#include "codegen/scan_layout_check.h"

#include <algorithm>
#include <set>
#include <string>

#include "codegen/scan_header_check.h"

namespace octopoint::prepare {

namespace fs = std::filesystem;

void failWithoutFloatAxis(const fs::path& path, const char* axis, const std::string& field_list) {
  fail(path, std::string("no float32 '") + axis + "' field: x, y and z are required",
       "field list: " + field_list);
}

void requireFloatXyz(const fs::path& path, const AsciiElement& point) {
  const auto& properties = point.properties;
  for (const char* axis : {"x", "y", "z"}) {
    const auto field = std::find_if(properties.begin(), properties.end(),
                                    [&](const AsciiProperty& p) { return p.name == axis; });
    const bool float32 = field != properties.end() && !field->is_list && field->repeat == 1 &&
                         field->type.kind == 'F' && field->type.size == 4;
    if (float32) continue;
    std::string names;
    for (const AsciiProperty& property : properties)
      names += (names.empty() ? "" : " ") + property.name;
    failWithoutFloatAxis(path, axis, printable(names));
  }
}

// PCL 1.13's PLY reader turns a vertex list into a field whose length the first vertex sets. A
// later list that is longer: with an int or uint count, on the last vertex, it aborts the process
// (assert(false) in vertexListPropertyContentCallback, the SIGABRT once seen); with a uchar or
// ushort count its surplus is written over the next vertex. A char or short count, or a list
// before x, y or z, it rejects without a reason. The preparer reads no vertex list: none is taken.
// A name given twice in an element makes PCL reject the file too (in a vertex always, in other
// elements when ascii): the PLY format names each of an element's properties once.
void checkPlyProperties(const fs::path& path, const AsciiElement& element) {
  std::set<std::string> seen;
  for (const AsciiProperty& property : element.properties) {
    const std::string where = "header line " + std::to_string(property.header_line);
    if (property.is_list && element.name == "vertex") {
      fail(path,
           "PLY vertex property '" + printable(property.name) +
               "' is a list: octopoint reads vertices of single values only",
           where);
    }
    if (!seen.insert(property.name).second) {
      fail(path,
           "PLY element '" + printable(element.name) + "' declares property '" +
               printable(property.name) + "' twice",
           where);
    }
  }
}

}  // namespace octopoint::prepare
