// Tests of read_text_matrix: the di-5 crop printed with %.17g, whitespace and
// comma separated, read back bit for bit; and every malformed file.
#include "halfspace/io/text_matrix_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/hdf5_test_support.hpp"
#include "io/reader_test_support.hpp"

namespace halfspace::io {
namespace {

namespace fs = std::filesystem;
using test::expect_contains;
using test::kFormatDataDir;
using test::TempDir;

// %.17g round-trips, and std::from_chars rounds correctly, so the brief's
// 1e-15 relative allowance for text is not even needed: we expect equality.
std::string matrix_error(const fs::path& path) {
  return test::file_error_of([&] { read_text_matrix(path); });
}

fs::path write_text(const TempDir& dir, const std::string& name, const std::string& text) {
  const fs::path path = dir / name;
  test::write_bytes(path, text);
  return path;
}

TEST(TextMatrixReaderTest, ReadsWhitespaceSeparatedMatrixBitExactly) {
  const HeightMap map = read_text_matrix(kFormatDataDir / "di-5-crop-space.txt");
  EXPECT_EQ(map.dimension, 2);
  EXPECT_EQ(map.nx, 64u);
  EXPECT_EQ(map.ny, 48u);
  EXPECT_EQ(map.dx, 0.0);
  test::expect_same_heights(map, test::di5_reference());
}

TEST(TextMatrixReaderTest, ReadsCommaSeparatedMatrixWithCommentsAndCrLfBitExactly) {
  const HeightMap map = read_text_matrix(kFormatDataDir / "di-5-crop-comma.csv");
  EXPECT_EQ(map.nx, 64u);
  EXPECT_EQ(map.ny, 48u);
  test::expect_same_heights(map, test::di5_reference());
}

TEST(TextMatrixReaderTest, AcceptsMixedSeparatorsTrailingCommasNaNAndUnits) {
  const TempDir dir;
  const fs::path path =
      write_text(dir, "m.txt", "\xEF\xBB\xBF# heights in um\n1.5, 2 ;3,\n\n  +4\t5e0   nan,\n% done\n");
  const HeightMap map = read_text_matrix(path, {"um", 1e-6});
  EXPECT_EQ(map.nx, 3u);
  EXPECT_EQ(map.ny, 2u);
  EXPECT_EQ(map.heights[0], 1.5 * 1e-6);
  EXPECT_EQ(map.heights[3], 4e-6);
  ASSERT_EQ(map.valid.size(), 6u);
  EXPECT_EQ(map.valid[5], 0);
  EXPECT_TRUE(std::isnan(map.heights[5]));
}

TEST(TextMatrixReaderTest, ReadsOneColumnAsProfile) {
  const TempDir dir;
  const HeightMap map = read_text_matrix(write_text(dir, "z.txt", "1\n2\n3\n"));
  EXPECT_EQ(map.dimension, 1);
  EXPECT_EQ(map.nx, 3u);
  EXPECT_EQ(map.ny, 1u);
}

TEST(TextMatrixReaderTest, RejectsRaggedRowsNamingTheLine) {
  const TempDir dir;
  const fs::path path = write_text(dir, "ragged.txt", "# c\n1 2 3\n4 5 6\n7 8\n");
  expect_contains(matrix_error(path), {path.string(), "line 4 has 2 values", "line 2", "has 3"});
}

TEST(TextMatrixReaderTest, RejectsWordsAndEmptyFieldsNamingLineAndField) {
  const TempDir dir;
  expect_contains(matrix_error(write_text(dir, "word.txt", "1 2\n3 abc\n")), {"line 2: field 2 'abc' is not a number"});
  expect_contains(matrix_error(write_text(dir, "empty.csv", "1,2,3\n4,,6\n")), {"line 2: field 2 is empty"});
  expect_contains(matrix_error(write_text(dir, "header.csv", "x,y\n1,2\n3,4\n")),
                  {"line 1: field 1 'x' is not a number", "comment lines start with # or %"});
  expect_contains(matrix_error(write_text(dir, "decimal-comma.txt", "1,5 2,5\n3,5 4.5.1\n")), {"line 2", "'4.5.1'"});
}

TEST(TextMatrixReaderTest, RejectsBinaryFilesNamingWhatTheyAre) {
  const TempDir dir;
  const fs::path npy = dir / "really-npy.txt";
  fs::copy_file(kFormatDataDir / "di-5-crop-c-le-f8.npy", npy);
  expect_contains(matrix_error(npy), {npy.string(), "not text", "NumPy", "set the format to npy"});
  const fs::path gsf = dir / "really-gsf.dat";
  fs::copy_file(kFormatDataDir / "di-5-crop-m.gsf", gsf);
  expect_contains(matrix_error(gsf), {"not text", "Gwyddion", "set the format to gsf"});
}

TEST(TextMatrixReaderTest, RejectsEmptyAndSingleValueFiles) {
  const TempDir dir;
  expect_contains(matrix_error(write_text(dir, "empty.txt", "# nothing\n\n")), {"holds no numbers"});
  expect_contains(matrix_error(write_text(dir, "one.txt", "42\n")), {"single number", "line 1"});
  expect_contains(matrix_error(dir / "missing.txt"), {"missing.txt", "does not exist"});
}

TEST(TextMatrixReaderTest, TruncatedLastRowIsReported) {
  const TempDir dir;
  const std::string full = test::read_bytes(kFormatDataDir / "di-5-crop-space.txt");
  const fs::path path = write_text(dir, "cut.txt", full.substr(0, full.size() - 200));
  expect_contains(matrix_error(path), {"line 48 has", "but line 1, the first data line, has 64"});
}

TEST(TextMatrixReaderTest, RefusesDevicesAtTheirFirstBytesAndNamesReadErrors) {
  // /dev/zero used to be read until memory ran out; /proc/self/mem gave
  // "basic_filebuf::underflow error" naming no file.
  expect_contains(matrix_error("/dev/zero"), {"/dev/zero", "not text: byte 0x00 at offset 0"});
  expect_contains(matrix_error("/proc/self/mem"), {"/proc/self/mem", "cannot be read", "Input/output error"});
}

TEST(TextMatrixReaderTest, ReadsFromAPipe) {
  const TempDir dir;
  const fs::path path = dir / "pipe.txt";
  const std::string text = "1 2 3\n4 5 6\n";
  test::EndlessPipe pipe(path, text, "", text.size());
  const HeightMap map = read_text_matrix(path);
  EXPECT_EQ(map.nx, 3u);
  EXPECT_EQ(map.ny, 2u);
  EXPECT_EQ(map.heights[5], 6.0);
}

TEST(TextMatrixReaderTest, EscapesControlBytesInMessages) {
  const TempDir dir;
  const std::string message = matrix_error(write_text(dir, "esc.txt",
                                                      "1 2\n3 \xc2\x9b"
                                                      "31m\n"));
  expect_contains(message, {"'\\xc2\\x9b31m' is not a number"});
  EXPECT_EQ(message.find("\xc2\x9b"), std::string::npos) << message;
}

}  // namespace
}  // namespace halfspace::io
