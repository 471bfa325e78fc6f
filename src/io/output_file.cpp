// The output-file rules and the atomic write (output_file.hpp), and the
// registry of temporaries that the signal handlers clean up.
#include "halfspace/io/output_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstring>
#include <memory>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "halfspace/error.hpp"

namespace halfspace::io {
namespace {

namespace fs = std::filesystem;

// Linux allows 40 links in one path resolution (path_resolution(7)).
constexpr int kMaxLinkHops = 40;

[[noreturn]] void fail(const fs::path& path, std::string_view reason) {
  throw FileError(fmt::format("cannot write output '{}': {}", path.string(), reason));
}

// "a character device", ...: what stands where a regular file should be.
std::string_view kind_of(fs::file_type type) {
  switch (type) {
    case fs::file_type::directory:
      return "a directory";
    case fs::file_type::character:
      return "a character device";
    case fs::file_type::block:
      return "a block device";
    case fs::file_type::fifo:
      return "a FIFO (named pipe)";
    case fs::file_type::socket:
      return "a socket";
    default:
      return "not a regular file";
  }
}

// A regular file or nothing may be at `where`; anything else would be
// replaced by the rename (a device node by a regular file, as root).
// Writes all of `bytes` (a write may write less than asked): 0, or the
// errno of the write that failed.
int write_all(int descriptor, std::span<const char> bytes) {
  const char* data = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    const ssize_t written = ::write(descriptor, data, left);
    if (written < 0) {
      if (errno != EINTR) return errno;
      continue;
    }
    data += written;
    left -= static_cast<std::size_t>(written);
  }
  return 0;
}

void require_regular_or_missing(const fs::path& shown, const fs::path& where, bool follow) {
  std::error_code error;
  const fs::file_status status = follow ? fs::status(where, error) : fs::symlink_status(where, error);
  // A missing directory, or a file where a directory should be, is named by
  // the directory check.
  if (error && error != std::errc::no_such_file_or_directory && error != std::errc::not_a_directory) {
    fail(shown, error.message());
  }
  if (!fs::exists(status) || fs::is_regular_file(status)) return;
  const std::string_view kind = kind_of(status.type());
  fail(shown, fmt::format("{} {}; an output must be a regular file or a new name (the finished file is renamed onto "
                          "the output path, which would replace it)",
                          where == shown ? "it is" : fmt::format("its target '{}' is", where.string()), kind));
}

void require_writable_directory(const fs::path& shown, const fs::path& target) {
  const fs::path directory = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code error;
  const fs::file_status status = fs::status(directory, error);
  if (!fs::exists(status)) fail(shown, fmt::format("directory '{}' does not exist", directory.string()));
  if (!fs::is_directory(status)) fail(shown, fmt::format("'{}' is not a directory", directory.string()));
  if (::access(directory.c_str(), W_OK) != 0) {
    fail(shown, fmt::format("directory '{}' is not writable: {}", directory.string(), std::strerror(errno)));
  }
}

// The registry of temporaries in progress, read by the signal handler. Only
// lock-free atomics and fixed arrays: a handler may not allocate or lock.
// A slot is free, being filled (invisible to the handler) or live.
constexpr int kFree = 0;
constexpr int kFilling = 1;
constexpr int kLive = 2;
constexpr std::size_t kSlots = 16;  // simultaneous writes; more are written unregistered
struct TemporarySlot {
  std::atomic<int> state{kFree};
  std::array<char, PATH_MAX> path{};
};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs lock-free atomics");
std::array<TemporarySlot, kSlots> temporaries;

}  // namespace

// Registers a temporary for removal on a signal while it exists. (Outside
// the anonymous namespace: OutputTemporary::Registration is one.)
class TemporaryRegistration {
 public:
  explicit TemporaryRegistration(const fs::path& temporary) {
    std::error_code error;
    const std::string absolute = fs::absolute(temporary, error).string();
    if (error || absolute.size() + 1 > PATH_MAX) return;  // not registered: removed only on ordinary failures
    for (std::size_t k = 0; k < kSlots; ++k) {
      int expected = kFree;
      if (temporaries[k].state.compare_exchange_strong(expected, kFilling, std::memory_order_acquire)) {
        std::memcpy(temporaries[k].path.data(), absolute.c_str(), absolute.size() + 1);
        temporaries[k].state.store(kLive, std::memory_order_release);
        slot_ = static_cast<int>(k);
        return;
      }
    }
  }
  TemporaryRegistration(const TemporaryRegistration&) = delete;
  TemporaryRegistration& operator=(const TemporaryRegistration&) = delete;
  ~TemporaryRegistration() { release(); }

  void release() {
    if (slot_ >= 0) temporaries[static_cast<std::size_t>(slot_)].state.store(kFree, std::memory_order_release);
    slot_ = -1;
  }

 private:
  int slot_ = -1;
};

namespace {

extern "C" void remove_temporaries_and_reraise(int signal) {
  const int saved_errno = errno;
  for (TemporarySlot& slot : temporaries) {
    if (slot.state.load(std::memory_order_acquire) == kLive) ::unlink(slot.path.data());
  }
  // The default action, delivered when the handler returns and unblocks the
  // signal: the process ends as if it had never been caught.
  struct sigaction default_action {};
  default_action.sa_handler = SIG_DFL;
  sigemptyset(&default_action.sa_mask);
  ::sigaction(signal, &default_action, nullptr);
  ::raise(signal);
  errno = saved_errno;
}

// Writes the temporary: created exclusively, so that nothing already there
// (a symlink planted in a shared directory, another writer's file) is
// followed or clobbered; fsynced, because without it a crash soon after the
// rename can leave an empty file under the final name (delayed allocation).
// The directory entry is not synced: a crash may lose the rename, and so the
// new file, but never yields a partial one. Removed again on failure.
void write_temporary(const fs::path& shown, const fs::path& temporary, std::span<const char> bytes) {
  const auto refuse_existing = [&] {
    fail(shown, fmt::format("temporary file '{}' already exists (left by an interrupted run?); remove it and retry",
                            temporary.string()));
  };
  // Registered before it is created, so that no signal finds it existing
  // but unregistered; the name is checked free first, so that a signal in
  // between removes nothing of anyone else's (the name holds our pid, so
  // only a leftover of an earlier process with the same pid can be there).
  struct stat existing {};
  if (::lstat(temporary.c_str(), &existing) == 0) refuse_existing();
  TemporaryRegistration registration(temporary);
  const int descriptor = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (descriptor < 0) {
    const int reason = errno;
    registration.release();
    if (reason == EEXIST) refuse_existing();
    fail(shown, fmt::format("could not create temporary file '{}': {}", temporary.string(), std::strerror(reason)));
  }
  int error = write_all(descriptor, bytes);
  // EINVAL: the file system cannot sync (some FUSE mounts); nothing to report.
  if (error == 0 && ::fsync(descriptor) != 0 && errno != EINVAL) error = errno;
  // Network file systems may report a failed write only at close.
  if (::close(descriptor) != 0 && error == 0 && errno != EINTR) error = errno;
  if (error != 0) {
    ::unlink(temporary.c_str());
    fail(shown, fmt::format("could not write temporary file '{}': {}", temporary.string(), std::strerror(error)));
  }
}

}  // namespace

fs::path output_target(const fs::path& path) {
  fs::path current = path;
  for (int hop = 0; hop <= kMaxLinkHops; ++hop) {
    std::error_code error;
    if (!fs::is_symlink(fs::symlink_status(current, error))) return current;
    const fs::path next = fs::read_symlink(current, error);
    if (error) fail(path, fmt::format("cannot read the symbolic link '{}': {}", current.string(), error.message()));
    current = next.is_absolute() ? next : current.parent_path() / next;
  }
  fail(path, "too many levels of symbolic links");
}

void check_output_path(const fs::path& path) {
  if (path.empty()) throw FileError("cannot write output: the output path is empty");
  if (!path.has_filename()) fail(path, "the path names a directory, not a file");
  // Followed first: /dev/stdout is a link to a pipe or terminal whose name
  // is not a path, and must be refused as what it is.
  require_regular_or_missing(path, path, true);
  const fs::path target = output_target(path);
  require_regular_or_missing(path, target, false);
  require_writable_directory(path, target);
}

bool same_file(const fs::path& output, const fs::path& other) {
  std::error_code error;
  if (fs::equivalent(output, other, error) && !error) return true;  // false (with an error) if either is missing
  const auto resolved = [](const fs::path& path) {
    std::error_code ignored;
    fs::path target = path;
    try {
      target = output_target(path);
    } catch (const FileError&) {
      // a loop of links: compare the names as given
    }
    const fs::path absolute = fs::absolute(target, ignored);
    const fs::path canonical = fs::weakly_canonical(absolute, ignored);
    return canonical.empty() ? absolute.lexically_normal() : canonical;
  };
  return resolved(output) == resolved(other);
}

void check_outputs_apart(std::span<const RunFile> outputs, std::span<const RunFile> inputs) {
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    for (const RunFile& input : inputs) {
      if (same_file(outputs[k].path, input.path)) {
        throw InputError(
            fmt::format("{} would overwrite the input {}: both are the file '{}'; choose another output name",
                        outputs[k].what, input.what, input.path.string()));
      }
    }
    for (std::size_t m = 0; m < k; ++m) {
      if (same_file(outputs[k].path, outputs[m].path)) {
        throw InputError(fmt::format("{} and {} are the same file '{}'; choose another output name", outputs[m].what,
                                     outputs[k].what, outputs[k].path.string()));
      }
    }
  }
}

namespace {

fs::path temporary_beside(const fs::path& target) {
  fs::path temporary = target;
  temporary += fmt::format(".tmp-{}", ::getpid());
  return temporary;
}

// The last step of an atomic write: the complete temporary renamed onto the
// target (checked once more: the first check may be minutes old), or removed.
void rename_onto_target(const fs::path& path, const fs::path& target, const fs::path& temporary) {
  const auto discard = [&] {
    std::error_code ignored;
    fs::remove(temporary, ignored);
  };
  try {
    require_regular_or_missing(path, target, false);
  } catch (const FileError&) {
    discard();
    throw;
  }
  std::error_code error;
  fs::rename(temporary, target, error);
  if (error) {
    discard();
    fail(path, fmt::format("could not rename temporary file '{}' onto it: {}", temporary.string(), error.message()));
  }
}

}  // namespace

void write_output_file(const fs::path& path, std::span<const char> bytes) {
  check_output_path(path);
  const fs::path target = output_target(path);
  const fs::path temporary = temporary_beside(target);
  write_temporary(path, temporary, bytes);
  rename_onto_target(path, target, temporary);
}

struct OutputTemporary::Registration : TemporaryRegistration {
  using TemporaryRegistration::TemporaryRegistration;
};

OutputTemporary::OutputTemporary(const fs::path& path)
    : path_(path), target_((check_output_path(path), output_target(path))), temporary_(temporary_beside(target_)) {
  write_temporary(path_, temporary_, {});
  // Registered after it exists (write_temporary's own registration ended
  // with it): a signal in between leaves it behind, as SIGKILL would.
  registration_ = std::make_unique<Registration>(temporary_);
}

OutputTemporary::~OutputTemporary() {
  if (!registration_) return;
  std::error_code ignored;
  fs::remove(temporary_, ignored);
}

void OutputTemporary::commit() {
  // Space reserved beyond the written size (reserve_output_space) is
  // released: a truncation to the file's own size frees it on ext4 and XFS.
  // The writers wrote through their own descriptors: synced here, so that a
  // crash soon after the rename cannot leave an empty file (write_temporary).
  const int descriptor = ::open(temporary_.c_str(), O_WRONLY | O_CLOEXEC);
  int error = descriptor < 0 ? errno : 0;
  struct stat status {};
  if (error == 0 && ::fstat(descriptor, &status) != 0) error = errno;
  if (error == 0 && ::ftruncate(descriptor, status.st_size) != 0) error = errno;
  if (error == 0 && ::fsync(descriptor) != 0 && errno != EINVAL) error = errno;
  if (descriptor >= 0) ::close(descriptor);
  if (error != 0) {
    fail(path_, fmt::format("could not write temporary file '{}': {}", temporary_.string(), std::strerror(error)));
  }
  rename_onto_target(path_, target_, temporary_);
  registration_.reset();
}

void write_output_set(std::span<const OutputBytes> files,
                      const std::function<void(std::size_t renamed)>& after_rename) {
  for (const OutputBytes& file : files) check_output_path(file.path);
  std::vector<std::unique_ptr<OutputTemporary>> temporaries;
  for (const OutputBytes& file : files) {
    temporaries.push_back(std::make_unique<OutputTemporary>(file.path));
    const fs::path& temporary = temporaries.back()->temporary();
    const int descriptor = ::open(temporary.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    int error = descriptor < 0 ? errno : write_all(descriptor, file.bytes);
    if (descriptor >= 0 && ::close(descriptor) != 0 && error == 0 && errno != EINTR) error = errno;
    if (error != 0) {
      fail(file.path, fmt::format("could not write temporary file '{}': {}", temporary.string(), std::strerror(error)));
    }
  }
  // The later files' old versions go before the first new one arrives.
  for (std::size_t k = 1; k < files.size(); ++k) {
    const fs::path target = output_target(files[k].path);
    if (::unlink(target.c_str()) != 0 && errno != ENOENT) {
      fail(files[k].path, fmt::format("could not remove the previous file, which would no longer match '{}': {}",
                                      files[0].path.string(), std::strerror(errno)));
    }
  }
  for (std::size_t k = 0; k < files.size(); ++k) {
    temporaries[k]->commit();  // fsyncs, then renames
    if (after_rename) after_rename(k);
  }
}

void reserve_output_space(const fs::path& path, const fs::path& temporary, std::uint64_t bytes) {
  const auto refuse = [&](int reason) {
    fail(path, fmt::format("could not reserve {} bytes for temporary file '{}': {}", bytes, temporary.string(),
                           std::strerror(reason)));
  };
  // A reservation that keeps the size is not held to the file-size limit,
  // which the writing would then meet.
  rlimit limit{};
  if (::getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY && bytes > limit.rlim_cur) {
    refuse(EFBIG);
  }
  const int descriptor = ::open(temporary.c_str(), O_WRONLY | O_CLOEXEC);
  if (descriptor < 0) refuse(errno);
  int error = 0;
  while (::fallocate(descriptor, FALLOC_FL_KEEP_SIZE, 0, static_cast<off_t>(bytes)) != 0) {
    if (errno == EINTR) continue;
    if (errno != EOPNOTSUPP) error = errno;
    break;
  }
  ::close(descriptor);
  if (error != 0) refuse(error);
}

void install_output_cleanup_on_signals() {
  for (const int signal : {SIGINT, SIGTERM, SIGHUP, SIGXFSZ}) {
    struct sigaction current {};
    if (::sigaction(signal, nullptr, &current) != 0) continue;
    const bool is_default = (current.sa_flags & SA_SIGINFO) == 0 && current.sa_handler == SIG_DFL;
    if (!is_default) continue;
    struct sigaction action {};
    action.sa_handler = remove_temporaries_and_reraise;
    sigemptyset(&action.sa_mask);
    // Each of these signals blocked while the handler runs, so that two of
    // them do not both re-raise half-way.
    for (const int other : {SIGINT, SIGTERM, SIGHUP, SIGXFSZ}) sigaddset(&action.sa_mask, other);
    ::sigaction(signal, &action, nullptr);
  }
}

}  // namespace halfspace::io
