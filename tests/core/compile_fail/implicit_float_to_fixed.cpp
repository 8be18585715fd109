// Compile-fail test: converting a double to a fixed-point number implicitly must not compile.
// Registered twice in ctest (see README.md): without OCTOPOINT_COMPILE_FAIL_CONTROL this file must
// FAIL to compile; with it, the same code written with the explicit API must compile, which proves
// the failure comes from the misuse and not from a broken include or typo.
#include "octopoint/fixed.h"

namespace {

octopoint::Q15 scale(octopoint::Q15 value) { return value; }

}  // namespace

int main() {
#ifdef OCTOPOINT_COMPILE_FAIL_CONTROL
  const octopoint::Q15 x = *octopoint::Q15::fromRatio(3, 2);  // explicit: 1.5
  return scale(x).roundToInt() == 2 ? 0 : 1;
#else
  const octopoint::Q15 x = 1.5;                     // must not compile: implicit double -> Q15
  return scale(2.5).roundToInt() + x.roundToInt();  // must not compile either: double argument
#endif
}
