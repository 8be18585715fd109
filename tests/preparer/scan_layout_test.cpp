// Layouts PCL 1.13 aborts on or rejects without saying why, and layouts we refuse after reading,
// refused from the header (and, for binary_compressed PCD, from its LZF stream) before PCL reads
// a byte of the body, with a message that says what and where. Also: the ascii body check reads
// only as far as a value or a run of white space can go before it refuses.

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "codegen/scan_header_check.h"
#include "tests/support/scan_loader_fixture.h"

namespace octopoint::prepare {
namespace {

const std::string kXyz = "property float x\nproperty float y\nproperty float z\n";

std::string plyHead(const std::string& format, const std::string& elements) {
  return "ply\nformat " + format + " 1.0\n" + elements + "end_header\n";
}

// One value of `bytes` bytes, little- or big-endian.
std::string word(std::uint64_t value, int bytes, bool big) {
  std::string out(static_cast<std::size_t>(bytes), '\0');
  for (int i = 0; i < bytes; ++i)
    out[static_cast<std::size_t>(big ? bytes - 1 - i : i)] = static_cast<char>(value >> (8 * i));
  return out;
}

// PCL 1.13 sizes a vertex list's field by the first vertex's list: with an int or uint count, a
// last vertex whose list is longer aborts the process (an assert: this test dies before the
// fix); with a uchar or ushort count a longer list is written over the next vertex; a char or
// short count, or a list before x, is rejected without a reason.
TEST_F(ScanLoaderTest, AVertexListPropertyIsRefusedFromTheHeader) {
  const std::vector<std::pair<std::string, int>> count_types = {
      {"uchar", 1}, {"char", 1}, {"short", 2}, {"ushort", 2}, {"int", 4}, {"uint", 4}};
  const std::string one = std::string("\0\0\x80\x3f", 4);  // 1.0f little-endian
  for (const auto& [count_type, count_bytes] : count_types) {
    for (const bool list_first : {false, true}) {
      const std::string declared = "property list " + count_type + " float extra\n";
      const std::string props = list_first ? declared + kXyz : kXyz + declared;
      const std::string line = list_first ? "4" : "7";
      for (const char* format : {"binary_little_endian", "binary_big_endian", "ascii"}) {
        const bool ascii = std::string(format) == "ascii";
        std::string body;  // lists of 1, 2 and 3 values: PCL's field takes the first's length
        for (int v = 0; v < 3; ++v) {
          const int length = v + 1;
          std::string list =
              ascii ? std::to_string(length)
                    : word(static_cast<std::uint64_t>(length), count_bytes, format[7] == 'b');
          for (int i = 0; i < length; ++i) list += ascii ? " 5" : one;
          const std::string xyz = ascii ? "1 2 3" : one + one + one;
          const std::string gap = ascii ? " " : "";
          body += (list_first ? list + gap + xyz : xyz + gap + list) + (ascii ? "\n" : "");
        }
        const fs::path path =
            writeBytes("list_" + count_type + (list_first ? "_first_" : "_last_") + format + ".ply",
                       plyHead(format, "element vertex 3\n" + props) + body);
        SCOPED_TRACE(path.string());
        expectError(path,
                    "PLY vertex property 'extra' is a list: octopoint reads vertices of "
                    "single values only (header line " +
                        line + ")");
      }
    }
  }
  // x itself as a list, and a list in another element (a mesh's faces), which PCL reads.
  expectError(writeBytes("x_list.ply", plyHead("ascii",
                                               "element vertex 1\nproperty list uchar "
                                               "float x\nproperty float y\n"
                                               "property float z\nend_header\n1 1 2 3\n")),
              "PLY vertex property 'x' is a list");
  const Scan faces = loadScan(writeBytes(
      "faces.ply", plyHead("ascii", "element vertex 3\n" + kXyz +
                                        "element face 1\nproperty list int int vertex_indices\n") +
                       "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
  EXPECT_EQ(faces.positions.size(), 3u);
}

// PCL rejects a vertex whose property name repeats (two fields of one name), and an ascii file
// where another element's does, saying only that it rejected the file.
TEST_F(ScanLoaderTest, APropertyDeclaredTwiceIsRefusedWithItsLine) {
  for (const std::string name : {"x", "z", "red", "intensity", "anything"}) {
    const std::string type = name == "red" ? "uchar" : "float";
    const std::string value = name == "red" ? "7" : "0.5";
    for (const std::string format : {"ascii", "binary_little_endian"}) {
      const std::string props = kXyz + "property " + type + " " + name + "\n";
      const std::string extra =
          name == "x" || name == "z" ? "" : "property " + type + " " + name + "\n";
      std::string body;
      const int values = 3 + 1 + (extra.empty() ? 0 : 1);
      if (format == "ascii") {
        for (int v = 0; v < 3; ++v)
          body += "1 2 3 " + value + (extra.empty() ? "" : " " + value) + "\n";
      } else {
        body = std::string(static_cast<std::size_t>(3 * 4 * values), '\0');
      }
      const fs::path path =
          writeBytes("twice_" + name + "_" + format + ".ply",
                     plyHead(format, "element vertex 3\n" + props + extra) + body);
      SCOPED_TRACE(path.string());
      const std::string line = extra.empty() ? "7" : "8";
      expectError(path, "PLY element 'vertex' declares property '" + name +
                            "' twice (header line " + line + ")");
    }
  }
  for (const std::string format : {"ascii", "binary_little_endian"}) {
    expectError(
        writeBytes("face_twice_" + format + ".ply",
                   plyHead(format, "element vertex 3\n" + kXyz +
                                       "element face 1\nproperty int a\nproperty int a\n") +
                       (format == "ascii" ? "0 0 0\n1 0 0\n0 1 0\n4 5\n" : std::string(44, '\0'))),
        "PLY element 'face' declares property 'a' twice (header line 9)");
  }
}

// ---- binary_compressed PCD: the LZF stream walked before PCL decompresses it ----

// A one-point binary_compressed PCD (12 bytes uncompressed) with `stream` as its LZF bytes, and
// the file byte where the stream starts.
std::pair<std::string, std::size_t> compressedPcd(const std::string& stream) {
  const std::string header =
      "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 1\nHEIGHT 1\n"
      "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 1\nDATA binary_compressed\n";
  return {header + word(stream.size(), 4, false) + word(12, 4, false) + stream, header.size() + 8};
}

TEST_F(ScanLoaderTest, ACorruptLzfStreamIsRefusedNamingTheFaultAndItsByte) {
  const std::string twelve("\x0b\0\0\x80\x3f\0\0\0\x40\0\0\x40\x40", 13);  // literal (1, 2, 3)
  const std::string four("\x03\1\2\3\4", 5);                               // literal of 4 bytes
  struct Case {
    std::string stream;
    std::size_t token;  // where the fault's token starts in the stream
    std::string what;
  };
  const std::vector<Case> cases = {
      {std::string("\x20\0", 2) + twelve, 0, "refers 1 bytes back after 0 bytes of output"},
      {four + std::string("\x20\x04", 2), 5, "refers 5 bytes back after 4 bytes of output"},
      {four + std::string("\xe0\0\x10", 3), 5, "refers 17 bytes back after 4 bytes of output"},
      {std::string("\x0b\1\2\3", 4), 0, "ends inside a literal run"},
      {four + "\x20", 5, "ends inside a back reference"},
      {four + "\xe0\x01", 5, "ends inside a back reference"},
      {twelve + std::string("\x20\0", 2), 13, "expands past the 12 bytes it declares"},
      {four + std::string("\x60\x03", 2) + four, 7, "expands past the 12 bytes it declares"},
      {four, 0, "expands to 4 bytes, not the 12 it declares"},
      {four + std::string("\x20\x03", 2), 0, "expands to 7 bytes, not the 12 it declares"},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto [bytes, stream_at] = compressedPcd(cases[i].stream);
    const fs::path path = writeBytes("lzf" + std::to_string(i) + ".pcd", bytes);
    SCOPED_TRACE(cases[i].what);
    ::testing::internal::CaptureStderr();
    const bool back = cases[i].what.rfind("refers", 0) == 0;
    expectError(path, "corrupt: binary_compressed data " + cases[i].what +
                          (back ? ", before its start" : "") + " (data at byte " +
                          std::to_string(stream_at + cases[i].token) + ")");
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  }
  // The same bytes, whole, load: a literal and back references that stay inside the output.
  const auto [good, at] = compressedPcd(four + std::string("\x20\x03\x60\x06", 4) + "\x00\x05");
  EXPECT_EQ(loadScan(writeBytes("good.pcd", good)).points_in_file, 1u);
}

// ---- x, y and z: refused from the header, before PCL reads a body of any size ----

TEST_F(ScanLoaderTest, XyzThatAreNotFloat32AreRefusedByTheHeaderCheckAlone) {
  const std::vector<std::pair<std::string, std::string>> pcd = {
      // SIZE / TYPE / COUNT of x
      {"8 4 4\nTYPE F F F\nCOUNT 1 1 1", "x"},
      {"4 4 1\nTYPE F F U\nCOUNT 1 1 1", "z"},
      {"4 4 4\nTYPE I F F\nCOUNT 1 1 1", "x"},
      {"4 4 4\nTYPE F F F\nCOUNT 1 2 1", "y"}};
  for (std::size_t i = 0; i < pcd.size(); ++i) {
    const std::string header = "VERSION 0.7\nFIELDS x y z\nSIZE " + pcd[i].first +
                               "\nWIDTH 2\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 2\n"
                               "DATA binary\n";
    const fs::path path =
        writeBytes("xyz" + std::to_string(i) + ".pcd", header + std::string(64, '\0'));
    SCOPED_TRACE(pcd[i].first);
    try {
      checkPcdHeader(path, fs::file_size(path));
      ADD_FAILURE() << "accepted";
    } catch (const PrepareError& error) {
      EXPECT_NE(std::string(error.what())
                    .find("no float32 '" + pcd[i].second +
                          "' field: x, y and z are required "
                          "(field list: x y z)"),
                std::string::npos)
          << error.what();
    }
  }
  const std::vector<std::pair<std::string, std::string>> ply = {
      {"property double x\nproperty float y\nproperty float z\n", "x"},
      {"property float x\nproperty uchar y\nproperty float z\n", "y"},
      {"property float x\nproperty float y\nproperty int z\n", "z"},
      {"property float x\nproperty float y\nproperty float w\n", "z"}};
  for (std::size_t i = 0; i < ply.size(); ++i) {
    for (const char* format : {"binary_little_endian", "binary_big_endian", "ascii"}) {
      const fs::path path = writeBytes("xyz" + std::to_string(i) + format + ".ply",
                                       plyHead(format, "element vertex 2\n" + ply[i].first) +
                                           "1 2 3\n4 5 6\n" + std::string(64, '\0'));
      SCOPED_TRACE(path.string());
      try {
        checkPlyHeader(path, fs::file_size(path));
        ADD_FAILURE() << "accepted";
      } catch (const PrepareError& error) {
        EXPECT_NE(std::string(error.what()).find("no float32 '" + ply[i].second + "' field"),
                  std::string::npos)
            << error.what();
      }
    }
  }
}

// ---- ascii bodies: how far the check reads before it refuses ----

// Bytes this process has read through read(2) and friends so far (/proc/self/io rchar).
std::uint64_t bytesRead() {
  std::ifstream io("/proc/self/io");
  for (std::string key; io >> key;) {
    std::uint64_t value = 0;
    io >> value;
    if (key == "rchar:") return value;
  }
  ADD_FAILURE() << "no rchar in /proc/self/io";
  return 0;
}

TEST_F(ScanLoaderTest, AnAsciiBodyOfNoValuesIsRefusedAfterReadingLittleOfIt) {
  constexpr std::uint64_t kBody = 32 << 20;  // 32 MiB; the check may read 1 MiB of head and 4 more
  const std::string pcd =
      "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 1000000\nHEIGHT 1\n"
      "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 1000000\nDATA ascii\n1 2 3\n";
  const std::string ply = plyHead("ascii", "element vertex 1000000\n" + kXyz) + "1 2 3\n";
  struct Case {
    std::string name;
    char fill;  // the body after one good line: NUL (a sparse file), digits, spaces, newlines
    std::string what;
  };
  const std::vector<Case> cases = {
      {"nul", '\0', "is not a float32"},
      {"digits", '7', "'7777777777"},
      {"spaces", ' ', "more than 65536 bytes of white space in a row"},
      {"newlines", '\n', "more than 65536 bytes of white space in a row"},
  };
  for (const Case& c : cases) {
    for (const std::string& head : {pcd, ply}) {
      const fs::path path = file(c.name + (head == pcd ? ".pcd" : ".ply"));
      std::ofstream(path, std::ios::binary) << head;
      if (c.fill == '\0') {
        fs::resize_file(path, head.size() + kBody);
      } else {
        std::ofstream out(path, std::ios::binary | std::ios::app);
        const std::string block(1 << 20, c.fill);
        for (std::uint64_t i = 0; i < kBody >> 20; ++i) out << block;
      }
      SCOPED_TRACE(path.string());
      const std::uint64_t before = bytesRead();
      try {
        head == pcd ? checkPcdHeader(path, fs::file_size(path))
                    : checkPlyHeader(path, fs::file_size(path));
        ADD_FAILURE() << "accepted";
      } catch (const PrepareError& error) {
        EXPECT_NE(std::string(error.what()).find(c.what), std::string::npos) << error.what();
      }
      EXPECT_LT(bytesRead() - before, std::uint64_t{5} << 20);
      fs::remove(path);
    }
  }
}

}  // namespace
}  // namespace octopoint::prepare
