// Helpers for the height-map reader tests: fixture paths, the di-5 reference
// crop, capturing a reader's FileError message, and writing damaged files.
#pragma once

#include <fcntl.h>
#include <gtest/gtest.h>
#include <pthread.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <Eigen/Core>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/height_map.hpp"
#include "halfspace/io/hdf5_height_map_reader.hpp"

namespace halfspace::test {

inline const std::filesystem::path kFormatDataDir = HALFSPACE_TEST_DATA_DIR;

// The shared data beside the project: <root>/../shared, where <root> is the
// source tree (tests/data is <root>/tests/data). The one place tests find it.
inline std::filesystem::path shared_data_dir() {
  return (kFormatDataDir / ".." / ".." / ".." / "shared").lexically_normal();
}
// The measured topographies (README.md, dektak-1.h5, di-5.h5, ...).
inline const std::filesystem::path kTopographyDir = shared_data_dir() / "data" / "topography";

inline bool have_topography() {
  return std::filesystem::exists(kTopographyDir / "README.md");
}

// The 48 x 64 crop of di-5.h5 that every format fixture of the map readers
// was written from (tests/data/make_format_fixtures.py).
inline HeightMap di5_reference() {
  return io::read_hdf5_height_map(kFormatDataDir / "di-5-crop-48x64.h5");
}

inline double rms_about_mean(const Eigen::ArrayXd& h) {
  return std::sqrt((h - h.mean()).square().mean());
}

// The message of the FileError that `read` throws; any other exception
// escapes and fails the test, and no exception is reported as a failure.
template <class Read>
std::string file_error_of(Read&& read) {
  try {
    read();
  } catch (const FileError& error) {
    return error.what();
  }
  ADD_FAILURE() << "reading did not throw FileError";
  return {};
}

inline void expect_contains(const std::string& message, const std::vector<std::string>& parts) {
  for (const std::string& part : parts) {
    EXPECT_NE(message.find(part), std::string::npos) << "message: " << message << "\nexpected to contain: " << part;
  }
}

// The process's peak resident memory so far (getrusage's high-water mark),
// in bytes: a reader that allocated gigabytes raises it for good.
inline std::size_t peak_resident_bytes() {
  struct rusage usage {};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<std::size_t>(usage.ru_maxrss) * 1024;  // ru_maxrss is in KiB on Linux
}

// Peak memory above today's peak that a refused hostile file may cost: the
// files claim gigabytes, a bounded reader takes a few megabytes.
inline constexpr std::size_t kRefusalMemoryAllowance = std::size_t{256} << 20;

// A FIFO at `path` whose writer sends `prefix` and then `filler` over and over
// until the reader goes away or `cap` bytes are out: an endless source, like
// /dev/zero but with a chosen start. written() tells how much a reader took.
class EndlessPipe {
 public:
  EndlessPipe(std::filesystem::path path, std::string prefix, std::string filler, std::size_t cap)
      : path_(std::move(path)) {
    if (::mkfifo(path_.c_str(), 0600) != 0) throw std::runtime_error("mkfifo " + path_.string());
    writer_ = std::thread([this, prefix = std::move(prefix), filler = std::move(filler), cap] {
      // SIGPIPE stays pending on this thread: a closed reader gives EPIPE.
      sigset_t pipe_signal;
      sigemptyset(&pipe_signal);
      sigaddset(&pipe_signal, SIGPIPE);
      pthread_sigmask(SIG_BLOCK, &pipe_signal, nullptr);
      const int fd = ::open(path_.c_str(), O_WRONLY | O_CLOEXEC);
      if (fd < 0) return;
      std::string piece = prefix;
      while (written_ < cap) {
        const ssize_t sent = ::write(fd, piece.data(), piece.size());
        if (sent <= 0) break;
        written_ += static_cast<std::size_t>(sent);
        piece = sent < static_cast<ssize_t>(piece.size()) ? piece.substr(static_cast<std::size_t>(sent)) : filler;
      }
      ::close(fd);
    });
  }
  EndlessPipe(const EndlessPipe&) = delete;
  EndlessPipe& operator=(const EndlessPipe&) = delete;
  ~EndlessPipe() {
    finish();
    ::unlink(path_.c_str());
  }

  // Waits for the writer; a reader that never opened the FIFO is stood in for.
  std::size_t written() {
    finish();
    return written_;
  }

 private:
  void finish() {
    if (!writer_.joinable()) return;
    const int fd = ::open(path_.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd >= 0) ::close(fd);
    writer_.join();
  }

  std::filesystem::path path_;
  std::thread writer_;
  std::size_t written_ = 0;
};

inline std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// Expects `map` to hold exactly the heights of `reference` (same shape),
// reporting the first difference.
inline void expect_same_heights(const HeightMap& map, const HeightMap& reference) {
  ASSERT_EQ(map.nx, reference.nx);
  ASSERT_EQ(map.ny, reference.ny);
  ASSERT_EQ(map.heights.size(), reference.heights.size());
  for (Eigen::Index k = 0; k < map.heights.size(); ++k) {
    if (map.heights[k] != reference.heights[k]) {
      ADD_FAILURE() << "first difference at (j, i) = (" << static_cast<std::size_t>(k) / map.nx << ", "
                    << static_cast<std::size_t>(k) % map.nx << "): " << map.heights[k] << " vs "
                    << reference.heights[k];
      return;
    }
  }
}

}  // namespace halfspace::test
