// The strict option parsing every tool shares (cli/numbers.h, cli/real_numbers.h,
// cli/arguments.h): the whole text is the value, it is range-checked, and the message names the
// option. Each wrapping or truncation the hardening sweep found (its class 7, docs/robustness.md)
// is a case here.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "cli/arguments.h"
#include "cli/error.h"
#include "cli/numbers.h"
#include "cli/real_numbers.h"
#include "cli/text.h"

namespace octopoint::cli {
namespace {

std::string messageOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const Error& error) {
    return error.what();
  }
  return "no error";
}

TEST(ParseInteger, TakesWholeNumbersInRange) {
  EXPECT_EQ(parseInteger("--depth", "8", 1, 16), 8);
  EXPECT_EQ(parseInteger("--depth", "+8", 1, 16), 8);
  EXPECT_EQ(parseInteger("--x", "-5", -10, 10), -5);
  EXPECT_EQ(parseInt("--x", "16", 1, 16), 16);
}

TEST(ParseInteger, RefusesWhatIsNotWholeOrOutOfRangeNamingTheOption) {
  EXPECT_EQ(messageOf([] { parseInt("--depth", "8.7", 1, 16); }),
            "--depth: '8.7' is not a whole number (1..16)");
  EXPECT_EQ(messageOf([] { parseInt("--depth", "1e300", 1, 16); }),
            "--depth: '1e300' is not a whole number (1..16)");
  EXPECT_EQ(messageOf([] { parseInt("--depth", "40", 1, 16); }), "--depth: 40 is outside 1..16");
  EXPECT_EQ(messageOf([] { parseInt("--depth", "0", 1, 16); }), "--depth: 0 is outside 1..16");
  EXPECT_EQ(messageOf([] { parseInt("--depth", "-1", 1, 16); }), "--depth: -1 is outside 1..16");
  // Past 64 bits: outside the range, never wrapped to a small number.
  EXPECT_EQ(messageOf([] { parseInt("--depth", "18446744073709551624", 1, 16); }),
            "--depth: 18446744073709551624 is outside 1..16");
  EXPECT_EQ(messageOf([] { parseInt("--depths", "2147483648", 1, 16); }),
            "--depths: 2147483648 is outside 1..16");
  for (const char* bad : {"", " 8", "8 ", "8x", "0x8", "++8", "+-8", "8,", "eight"}) {
    EXPECT_NE(messageOf([&] { parseInt("--depth", bad, 1, 16); }).find("is not a whole number"),
              std::string::npos)
        << bad;
  }
}

TEST(ParseIntList, TakesAscendingListsAndRefusesTheRestByItem) {
  EXPECT_EQ(parseIntList("--depths", "7,8", 1, 16, 8, ListOrder::kStrictlyAscending),
            (std::vector<int>{7, 8}));
  EXPECT_EQ(parseIntList("--f", "9,3,3", 1, 16, 8, ListOrder::kAny), (std::vector<int>{9, 3, 3}));
  EXPECT_EQ(
      messageOf([] { parseIntList("--depths", "0", 1, 16, 8, ListOrder::kStrictlyAscending); }),
      "--depths: 0 is outside 1..16");
  EXPECT_EQ(
      messageOf([] { parseIntList("--depths", "8,7", 1, 16, 8, ListOrder::kStrictlyAscending); }),
      "--depths: '8,7' is not strictly ascending");
  EXPECT_EQ(
      messageOf([] { parseIntList("--depths", "7,,8", 1, 16, 8, ListOrder::kStrictlyAscending); }),
      "--depths: item 2 of '7,,8' is empty (give a comma-separated list of whole numbers)");
  EXPECT_EQ(
      messageOf([] { parseIntList("--depths", "", 1, 16, 8, ListOrder::kStrictlyAscending); }),
      "--depths: item 1 of '' is empty (give a comma-separated list of whole numbers)");
  EXPECT_EQ(
      messageOf([] { parseIntList("--depths", "1,2,3", 1, 16, 2, ListOrder::kStrictlyAscending); }),
      "--depths: '1,2,3' has more than 2 items");
}

TEST(ParseFrameSize, TakesWxHAndRefusesWrapsAndHugeFrames) {
  const FrameSize size = parseFrameSize("--size", "320x240", 1, 8192);
  EXPECT_EQ(size.width, 320);
  EXPECT_EQ(size.height, 240);
  // 4294967616 = 2^32 + 320: sscanf("%d") took it as 320.
  EXPECT_EQ(messageOf([] { parseFrameSize("--size", "4294967616x240", 1, 8192); }),
            "--size: '4294967616x240' is not WxH with each side in 1..8192");
  EXPECT_EQ(messageOf([] { parseFrameSize("--size", "0x10", 1, 8192); }),
            "--size: '0x10' is not WxH with each side in 1..8192");
  EXPECT_EQ(messageOf([] { parseFrameSize("--size", "320x240x3", 1, 8192); }),
            "--size: '320x240x3' is not WxH with each side in 1..8192");
  EXPECT_EQ(messageOf([] { parseFrameSize("--size", "8192x8192", 1, 8192, 4096 * 4096); }),
            "--size: 8192x8192 is 67108864 pixels, at most 16777216");
}

TEST(ParseChoice, NamesTheChoices) {
  EXPECT_EQ(parseChoice("--axes", "y-up", {"y-down", "y-up"}), 1u);
  EXPECT_EQ(messageOf([] {
              parseChoice("--axes", "z", {"y-down", "y-up"});
            }),
            "--axes: 'z' is not one of y-down, y-up");
}

TEST(ParseReal, TakesFiniteNumbersInRangeOnly) {
  EXPECT_DOUBLE_EQ(parseReal("--zoom", "1.5", 0, 10), 1.5);
  EXPECT_DOUBLE_EQ(parseReal("--zoom", "+2e-1", 0, 10), 0.2);
  EXPECT_DOUBLE_EQ(parseReal("--yaw", "1e-400", -1, 1), 0.0);  // underflow is zero, not an error
  EXPECT_EQ(messageOf([] { parseReal("--zoom", "1e400", 0, 10); }),
            "--zoom: 1e400 is outside 0..10");
  EXPECT_EQ(messageOf([] { parseReal("--zoom", "11", 0, 10); }), "--zoom: 11 is outside 0..10");
  for (const char* bad : {"", "nan", "inf", "-inf", "1.5x", " 1", "0x10", "1,5", "--1"}) {
    EXPECT_NE(messageOf([&] { parseReal("--zoom", bad, -100, 100); }).find("--zoom: "),
              std::string::npos)
        << bad;
    EXPECT_EQ(messageOf([&] { parseReal("--zoom", bad, -100, 100); }).find("no error"),
              std::string::npos)
        << bad;
  }
  EXPECT_EQ(messageOf([] { parseZoom("--zoom", "0"); }), "--zoom: 0 is outside 1/65536..32767");
  EXPECT_EQ(parseZoom("--zoom", "1.5").raw(), 3 * 32768);
  EXPECT_EQ(parseDegrees("--yaw", "-90"), Angle::fromDegrees(-90));
  EXPECT_EQ(messageOf([] { parseDegrees("--yaw", "1e300"); }),
            "--yaw: 1e300 is outside -1000000..1000000");
}

struct Argv {
  explicit Argv(std::vector<std::string> args) : strings(std::move(args)) {
    for (std::string& s : strings) pointers.push_back(s.data());
  }
  int argc() const { return static_cast<int>(pointers.size()); }
  char** argv() { return pointers.data(); }
  std::vector<std::string> strings;
  std::vector<char*> pointers;
};

TEST(ArgumentReader, ReadsValuesSwitchesAndPlainArguments) {
  Argv argv({"tool", "--size", "1x2", "--fill", "scan.pcd", "--yaw=-30", "-o", "-"});
  ArgumentReader args(argv.argc(), argv.argv());
  ASSERT_TRUE(args.next());
  EXPECT_TRUE(args.is("--size"));
  EXPECT_EQ(args.value(), "1x2");
  ASSERT_TRUE(args.next());
  EXPECT_TRUE(args.is("--fill"));
  args.noValue();
  ASSERT_TRUE(args.next());
  EXPECT_TRUE(args.isPlain());
  EXPECT_EQ(args.current(), "scan.pcd");
  ASSERT_TRUE(args.next());
  EXPECT_TRUE(args.is("--yaw"));
  EXPECT_EQ(args.value(), "-30");
  ASSERT_TRUE(args.next());
  EXPECT_EQ(args.value(), "-");
  EXPECT_FALSE(args.next());
}

TEST(ArgumentReader, RefusesMissingValuesUnknownOptionsAndCutsWhatItEchoes) {
  Argv missing({"tool", "--size"});
  ArgumentReader a(missing.argc(), missing.argv());
  ASSERT_TRUE(a.next());
  EXPECT_EQ(messageOf([&] { a.value(); }), "--size: missing value (see --help)");
  Argv unknown({"tool", "--frobnicate" + std::string(5000, 'x')});
  ArgumentReader b(unknown.argc(), unknown.argv());
  ASSERT_TRUE(b.next());
  const std::string message = messageOf([&] { b.refuseUnknown(); });
  EXPECT_EQ(message, "unknown option '--frobnicate" + std::string(kMaxQuoted - 12, 'x') +
                         "...' (see --help)");
  Argv switched({"tool", "--fill=yes"});
  ArgumentReader c(switched.argc(), switched.argv());
  ASSERT_TRUE(c.next());
  EXPECT_EQ(messageOf([&] { c.noValue(); }), "--fill: takes no value, got 'yes'");
}

TEST(Text, PrintableOneLineAndShort) {
  EXPECT_EQ(printable("a\nb\tc"), "a?b?c");
  EXPECT_EQ(inQuotes(std::string(50, 'k')), "'" + std::string(40, 'k') + "...'");
  EXPECT_EQ(oneLine("one\ntwo\r"), "one two ");
  const std::string long_path = "/" + std::string(300, 'd') + "/scan.pcd";
  const std::string shown = displayPath(long_path);
  EXPECT_LE(shown.size(), kMaxPathShown + 3);
  EXPECT_EQ(shown.substr(shown.size() - 9), "/scan.pcd");
}

// Numbers in messages read back as the number given: every digit kept, plain where short.
TEST(RealText, ReadsBackAsTheSameNumber) {
  EXPECT_EQ(realText(1000000.0625), "1000000.0625");
  EXPECT_EQ(realText(1e6), "1000000");
  EXPECT_EQ(realText(-90), "-90");
  EXPECT_EQ(realText(0), "0");
  EXPECT_EQ(realText(0.1), "0.1");
  EXPECT_EQ(realText(1e-300), "1e-300");
  EXPECT_EQ(realText(1.5e300), "1.5e+300");
  for (const double value : {1000000.0625, 123456.789, 3.0e-7, 9.999999999999998e15, 1e16, -2.5e-7,
                             0.30000000000000004, 65536.0 + 1.0 / 65536}) {
    EXPECT_EQ(std::stod(realText(value)), value) << realText(value);
  }
  EXPECT_EQ(messageOf([] { parseReal("--zoom", "1000000.0625", 0, 10); }),
            "--zoom: 1000000.0625 is outside 0..10");
  EXPECT_EQ(messageOf([] { parseReal("--zoom", "11", 0.0625, 10.5); }),
            "--zoom: 11 is outside 0.0625..10.5");
}

}  // namespace
}  // namespace octopoint::cli
