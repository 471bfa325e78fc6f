// Tests of the output-file rules (io/output_file.hpp): what may stand at an
// output path, symbolic links followed to their target, the same-file test
// behind the CLI's collision checks, and the atomic write.
#include "halfspace/io/output_file.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/io/hdf5_output.hpp"
#include "io/hdf5_test_support.hpp"
#include "support/program_run.hpp"

namespace halfspace::io {
namespace {

namespace fs = std::filesystem;
using test::TempDir;
using testing::read_text;

// The FileError message of check_output_path(path), or "" if it passed.
std::string refusal(const fs::path& path) {
  try {
    check_output_path(path);
  } catch (const FileError& error) {
    return error.what();
  }
  return "";
}

std::string write_refusal(const fs::path& path, const std::string& text) {
  try {
    write_output_file(path, text);
  } catch (const FileError& error) {
    return error.what();
  }
  return "";
}

// A listening-less Unix socket bound at `path`; returns its descriptor.
int bind_socket(const fs::path& path) {
  const int descriptor = ::socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  std::strncpy(address.sun_path, path.c_str(), sizeof(address.sun_path) - 1);
  if (::bind(descriptor, reinterpret_cast<const sockaddr*>(&address), sizeof(address)) != 0) {
    ::close(descriptor);
    return -1;
  }
  return descriptor;
}

TEST(OutputFileTest, AcceptsANewNameAndARegularFile) {
  const TempDir dir;
  EXPECT_EQ(refusal(dir / "new.h5"), "");
  std::ofstream(dir / "old.h5") << "old";
  EXPECT_EQ(refusal(dir / "old.h5"), "");
}

// The rename would replace whatever is there: a device node by a regular
// file when run as root. Each kind is refused by name, and nothing is
// touched by a write either.
TEST(OutputFileTest, RefusesDevicesFifosDirectoriesAndSocketsNamingThem) {
  const TempDir dir;
  // /dev/null is only checked, never written, whatever the code under test does.
  const std::string null_message = refusal("/dev/null");
  EXPECT_NE(null_message.find("cannot write output '/dev/null': it is a character device"), std::string::npos)
      << null_message;

  ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);
  fs::create_directory(dir / "folder");
  const int socket = bind_socket(dir / "socket");
  ASSERT_GE(socket, 0);
  const struct {
    const char* name;
    const char* kind;
    fs::file_type type;
  } cases[] = {{"pipe", "it is a FIFO (named pipe)", fs::file_type::fifo},
               {"folder", "it is a directory", fs::file_type::directory},
               {"socket", "it is a socket", fs::file_type::socket}};
  for (const auto& c : cases) {
    const fs::path path = dir / c.name;
    SCOPED_TRACE(path.string());
    const std::string message = refusal(path);
    EXPECT_NE(message.find(fmt::format("cannot write output '{}': {}", path.string(), c.kind)), std::string::npos)
        << message;
    EXPECT_NE(message.find("must be a regular file"), std::string::npos) << message;
    EXPECT_NE(write_refusal(path, "data"), "");
    EXPECT_EQ(fs::symlink_status(path).type(), c.type) << "replaced";
  }
  ::close(socket);

  // A device node of our own (the null device's numbers), where permitted.
  const fs::path device = dir / "null-device";
  if (::mknod(device.c_str(), S_IFCHR | 0600, makedev(1, 3)) == 0) {
    EXPECT_NE(write_refusal(device, "data").find("it is a character device"), std::string::npos);
    EXPECT_EQ(fs::symlink_status(device).type(), fs::file_type::character) << "the device node was replaced";
  }
  for (const std::string& name : dir.entries()) EXPECT_EQ(name.find(".tmp-"), std::string::npos) << name;
}

// Followed: the temporary goes beside the target and is renamed onto it, so
// the link stays a link and the file it names gets the new contents.
TEST(OutputFileTest, FollowsASymbolicLinkToItsTarget) {
  const TempDir dir;
  fs::create_directory(dir / "data");
  std::ofstream(dir / "data" / "result.h5") << "old";
  fs::create_symlink("data/result.h5", dir / "link.h5");
  write_output_file(dir / "link.h5", std::string("new"));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir / "link.h5")));
  EXPECT_EQ(read_text(dir / "data" / "result.h5"), "new");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"data", "link.h5"}));
  EXPECT_EQ(output_target(dir / "link.h5"), dir / "data" / "result.h5");

  // A dangling link creates its target, as a shell's redirection does.
  fs::create_symlink("data/fresh.h5", dir / "dangling.h5");
  write_output_file(dir / "dangling.h5", std::string("fresh"));
  EXPECT_EQ(read_text(dir / "data" / "fresh.h5"), "fresh");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir / "dangling.h5")));

  // A link to a FIFO is refused like the FIFO.
  ASSERT_EQ(::mkfifo((dir / "data" / "pipe").c_str(), 0600), 0);
  fs::create_symlink("data/pipe", dir / "to-pipe");
  EXPECT_NE(refusal(dir / "to-pipe").find("FIFO"), std::string::npos);
  EXPECT_EQ(fs::symlink_status(dir / "data" / "pipe").type(), fs::file_type::fifo);

  // A loop of links is named, not followed forever.
  fs::create_symlink("loop-b", dir / "loop-a");
  fs::create_symlink("loop-a", dir / "loop-b");
  EXPECT_NE(refusal(dir / "loop-a").find("symbolic links"), std::string::npos) << refusal(dir / "loop-a");
}

TEST(OutputFileTest, SameFileSeesThroughNamesLinksAndHardLinks) {
  const TempDir dir;
  fs::create_directory(dir / "sub");
  std::ofstream(dir / "map.h5") << "heights";
  fs::create_symlink("map.h5", dir / "alias.h5");
  fs::create_hard_link(dir / "map.h5", dir / "hard.h5");
  EXPECT_TRUE(same_file(dir / "map.h5", dir / "sub" / ".." / "map.h5"));
  EXPECT_TRUE(same_file(dir / "alias.h5", dir / "map.h5"));
  EXPECT_TRUE(same_file(dir / "hard.h5", dir / "map.h5"));
  EXPECT_TRUE(same_file(dir / "new.h5", dir / "sub" / ".." / "new.h5")) << "neither exists yet";
  EXPECT_FALSE(same_file(dir / "map.csv", dir / "map.h5"));
  EXPECT_FALSE(same_file(dir / "sub" / "map.h5", dir / "map.h5"));
}

TEST(OutputFileTest, WritesAtomicallyAndLeavesNoTemporary) {
  const TempDir dir;
  std::ofstream(dir / "table.csv") << "old contents";
  write_output_file(dir / "table.csv", std::string("a,b\n1,2\n"));
  EXPECT_EQ(read_text(dir / "table.csv"), "a,b\n1,2\n");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"table.csv"});
  const std::string message = write_refusal(dir / "missing" / "t.csv", "x");
  EXPECT_NE(message.find("directory '" + (dir / "missing").string() + "' does not exist"), std::string::npos)
      << message;
}

// A set of files ended between its renames, in a child process: by SIGKILL
// it leaves the first file new, the second's old version removed and its
// temporary behind; by SIGTERM (with the cleanup handlers) the same without
// the temporary. Never the new first file beside the old second one (a
// sweep's new .h5 beside the previous .csv).
std::vector<std::string> set_killed_between_renames(const TempDir& dir, int signal) {
  std::ofstream(dir / "a.h5") << "old a";
  std::ofstream(dir / "a.csv") << "old b";
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child == 0) {
    if (signal == SIGTERM) install_output_cleanup_on_signals();
    const std::string a = "new a";
    const std::string b = "new b";
    const OutputBytes files[] = {{dir / "a.h5", a}, {dir / "a.csv", b}};
    write_output_set(files, [&](std::size_t renamed) {
      if (renamed == 0) ::raise(signal);
    });
    ::_exit(0);
  }
  int status = 0;
  EXPECT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal) << status;
  EXPECT_EQ(read_text(dir / "a.h5"), "new a");
  std::vector<std::string> entries = dir.entries();
  const std::string leftover = fmt::format("a.csv.tmp-{}", child);
  for (std::string& entry : entries) {
    if (entry == leftover) entry = "a.csv.tmp-<pid>";
  }
  return entries;
}

TEST(OutputFileTest, SetEndedBetweenRenamesLeavesNoMismatchedPair) {
  {
    const TempDir dir;
    EXPECT_EQ(set_killed_between_renames(dir, SIGKILL), (std::vector<std::string>{"a.csv.tmp-<pid>", "a.h5"}));
  }
  {
    const TempDir dir;
    EXPECT_EQ(set_killed_between_renames(dir, SIGTERM), (std::vector<std::string>{"a.h5"}));
  }
  // Not interrupted: both new, nothing else; a refused path changes nothing.
  const TempDir dir;
  std::ofstream(dir / "a.csv") << "old b";
  const std::string a = "new a";
  const std::string b = "new b";
  const OutputBytes files[] = {{dir / "a.h5", a}, {dir / "a.csv", b}};
  write_output_set(files);
  EXPECT_EQ(read_text(dir / "a.h5"), "new a");
  EXPECT_EQ(read_text(dir / "a.csv"), "new b");
  const OutputBytes refused[] = {{dir / "a.h5", b}, {dir / "missing" / "a.csv", a}};
  EXPECT_THROW(write_output_set(refused), FileError);
  EXPECT_EQ(read_text(dir / "a.h5"), "new a");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"a.csv", "a.h5"}));
}

// The large-file path: the writer fills the temporary in place. A writer
// that fails leaves the old file and no temporary; one that succeeds
// replaces the file.
TEST(OutputFileTest, WriterInPlaceIsAtomicToo) {
  const TempDir dir;
  const fs::path path = dir / "big.h5";
  std::ofstream(path) << "old contents";
  const auto values = std::vector<double>(6 * 4 * 5, 1.5);
  EXPECT_THROW(write_large_hdf5_file(path, 1 << 20,
                                     [&](const Hdf5Node& root) {
                                       const Hdf5Node field = root.create_dataset("field", {6, 4, 5}, "Pa");
                                       field.write_slabs(0, std::span<const double>(values).first(40));
                                       throw InputError("stopped half-way");
                                     }),
               InputError);
  EXPECT_EQ(read_text(path), "old contents");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"big.h5"});

  write_large_hdf5_file(path, 1 << 20, [&](const Hdf5Node& root) {
    const Hdf5Node field = root.create_dataset("field", {6, 4, 5}, "Pa");
    field.write_slabs(0, std::span<const double>(values).first(40));
    field.write_slabs(2, std::span<const double>(values).subspan(40));
    // Slabs beyond the dataset are refused.
    EXPECT_THROW(field.write_slabs(5, std::span<const double>(values).first(40)), InputError);
  });
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"big.h5"});
  const test::H5 file = test::open_file(path);
  EXPECT_EQ(test::read_dataset<double>(file.get(), "/field", H5T_NATIVE_DOUBLE), values);
}

// The reservation meets the file-size limit (like a full disk) before HDF5
// writes anything: a FileError naming the reason, and no temporary left.
TEST(OutputFileTest, ReservationFailureLeavesNoTemporary) {
  constexpr rlim_t kSizeLimit = 1 << 20;
  const TempDir dir;
  rlimit saved{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
  if (saved.rlim_max != RLIM_INFINITY && saved.rlim_max < kSizeLimit) GTEST_SKIP() << "file size limit already low";
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit limited = saved;
  limited.rlim_cur = kSizeLimit;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &limited), 0);
  bool filled = false;
  std::string message;
  try {
    write_large_hdf5_file(dir / "big.h5", 64 << 20, [&](const Hdf5Node&) { filled = true; });
  } catch (const FileError& error) {
    message = error.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, old_handler);
  EXPECT_FALSE(filled);
  EXPECT_NE(message.find("cannot write output '" + (dir / "big.h5").string() + "'"), std::string::npos) << message;
  EXPECT_NE(message.find("could not reserve"), std::string::npos) << message;
  EXPECT_NE(message.find(std::strerror(EFBIG)), std::string::npos) << message;
  EXPECT_TRUE(dir.entries().empty());
}

// The atomic write of a writer that writes the file itself by name.
TEST(OutputFileTest, OutputTemporaryIsRenamedOnCommitAndRemovedOtherwise) {
  const TempDir dir;
  std::ofstream(dir / "result.h5") << "old contents";
  {
    OutputTemporary output(dir / "result.h5");
    EXPECT_EQ(output.temporary().parent_path(), dir.path());
    EXPECT_TRUE(fs::is_regular_file(output.temporary()));
    std::ofstream(output.temporary()) << "new contents";
    EXPECT_EQ(read_text(dir / "result.h5"), "old contents") << "replaced before commit";
    output.commit();
  }
  EXPECT_EQ(read_text(dir / "result.h5"), "new contents");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"result.h5"});
  {
    OutputTemporary abandoned(dir / "result.h5");
    std::ofstream(abandoned.temporary()) << "never finished";
  }
  EXPECT_EQ(read_text(dir / "result.h5"), "new contents");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"result.h5"}) << "the abandoned temporary is left";
  try {
    OutputTemporary refused(dir / "missing" / "result.h5");
    ADD_FAILURE() << "an output in a missing directory was accepted";
  } catch (const FileError& error) {
    EXPECT_NE(std::string(error.what()).find("does not exist"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace halfspace::io
