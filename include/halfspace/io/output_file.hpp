// Every file halfspace writes goes through here: the path rules, the atomic
// write (temporary file beside the target, fsync, rename) and the cleanup of
// temporaries when the program is interrupted (docs/usage.md#output-files).
//
// Rules. The output path must name a regular file or nothing: a directory,
// device, FIFO or socket there is refused, never replaced. A symbolic link is
// followed: the temporary is written beside the link's final target and
// renamed onto the target, so the link stays and the file it points to gets
// the new contents.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <string>

namespace halfspace::io {

// Checks that `path` can receive an output file: the name is not empty and
// names a file, the (link-resolved) target is a regular file or does not
// exist, and its directory exists and is writable. Throws FileError
// "cannot write output '<path>': <reason>", naming what is in the way (for
// example "it is a character device"). Called again by write_output_file, so
// an early call only moves the refusal before a long computation.
void check_output_path(const std::filesystem::path& path);

// Where the bytes written to `path` end up: `path` itself, or the final
// target of the chain of symbolic links at `path` (which may not exist yet).
// Throws FileError for a loop of links.
std::filesystem::path output_target(const std::filesystem::path& path);

// Whether writing `output` would replace the file at `other` (an input or
// another output of the same run): the same path after resolving symbolic
// links, "..", and relative names, or the same existing file under another
// name (a hard link).
bool same_file(const std::filesystem::path& output, const std::filesystem::path& other);

// A file of a run and how its messages name it ("--output f.h5").
struct RunFile {
  std::string what;
  std::filesystem::path path;
};

// Throws InputError where an output would replace one of `inputs` or an
// earlier output (same_file), naming both and the file.
void check_outputs_apart(std::span<const RunFile> outputs, std::span<const RunFile> inputs);

// Writes `bytes` to `path` atomically: checks the path (as above), creates
// `<target>.tmp-<pid>` exclusively beside the target, writes and fsyncs it,
// and renames it onto the target. A reader sees the old file or the complete
// new one, never a partial file. Throws FileError "cannot write output
// '<path>': <reason>"; on failure the temporary is removed and an existing
// file at `path` is left untouched.
void write_output_file(const std::filesystem::path& path, std::span<const char> bytes);

// The same atomic write for a writer that writes the file itself, by name
// (the parallel HDF5 writer of an MPI run, whose processes all write into
// it; the stress volume, too large to assemble in memory): the constructor
// checks the path as above and creates an empty `<target>.tmp-<pid>`
// exclusively beside the target, registered for removal on the signals
// below; commit() releases any space reserved beyond the written size
// (reserve_output_space), syncs it and renames it onto the target; never
// committed, it is removed by the destructor. Throws FileError "cannot write
// output '<path>': <reason>".
class OutputTemporary {
 public:
  explicit OutputTemporary(const std::filesystem::path& path);
  ~OutputTemporary();
  OutputTemporary(const OutputTemporary&) = delete;
  OutputTemporary& operator=(const OutputTemporary&) = delete;

  // Where the writer writes.
  const std::filesystem::path& temporary() const { return temporary_; }
  void commit();

 private:
  struct Registration;
  std::filesystem::path path_;
  std::filesystem::path target_;
  std::filesystem::path temporary_;
  std::unique_ptr<Registration> registration_;
};

// One file of a set that write_output_set writes.
struct OutputBytes {
  std::filesystem::path path;
  std::span<const char> bytes;
};

// Writes several files that belong together (a sweep's .h5 and .csv): every
// path is checked and every temporary written first (a failure there
// changes nothing); then the existing files at the later paths are removed,
// and the temporaries are renamed in order. So a process ended between two
// renames, even by SIGKILL, leaves the earlier files new and the later ones
// absent (SIGKILL: and their temporaries), never an old file beside a new
// one. `after_rename(k)`, if given, runs after file k is in place (a test's
// seam). Throws FileError "cannot write output '<path>': <reason>".
void write_output_set(std::span<const OutputBytes> files,
                      const std::function<void(std::size_t renamed)>& after_rename = {});

// Reserves `bytes` of disk space for the file at `temporary` (an
// OutputTemporary's, once its writer has created it) without changing its
// size (fallocate, FALLOC_FL_KEEP_SIZE), so that a full disk or the
// file-size limit shows up here, before anything is written, rather than
// half-way through. Where the file system cannot reserve (EOPNOTSUPP) it
// does nothing. Throws FileError "cannot write output '<path>': could not
// reserve N bytes for temporary file '...': <reason>".
void reserve_output_space(const std::filesystem::path& path, const std::filesystem::path& temporary,
                          std::uint64_t bytes);

// Installs handlers for SIGINT, SIGTERM, SIGHUP and SIGXFSZ that remove the
// temporaries of writes in progress and then end the process by the same
// signal with its default action (exit status and core dumps as without the
// handler). Signals whose disposition is not the default (ignored by the
// shell for background jobs, or handled by the application) are left alone.
// SIGKILL cannot be handled: it may leave a `<name>.tmp-<pid>` file behind.
// Call once, early, from the program's main thread.
void install_output_cleanup_on_signals();

}  // namespace halfspace::io
