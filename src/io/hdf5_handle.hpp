// Private RAII owners for HDF5 identifiers (hid_t), a guard that keeps HDF5
// from printing its error stack, and a helper that turns the error stack into
// a short reason for our own exception messages.
#pragma once

#include <hdf5.h>

#include <string>
#include <utility>

namespace halfspace::io::detail {

// Owns one HDF5 identifier and closes it with `Close` (H5Fclose, H5Dclose, ...).
// Never wrap predefined types such as H5T_NATIVE_DOUBLE: they are not ours to close.
template <herr_t (*Close)(hid_t)>
class Handle {
 public:
  Handle() = default;
  explicit Handle(hid_t id) : id_(id) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, H5I_INVALID_HID)) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, H5I_INVALID_HID);
    }
    return *this;
  }
  ~Handle() { reset(); }

  hid_t get() const { return id_; }
  // HDF5 calls that create or open return a negative id on failure.
  bool valid() const { return id_ >= 0; }

  // Closes now and reports success. Closing a file flushes it, so a writer
  // must see this status instead of losing it in the destructor.
  bool close() {
    const herr_t status = valid() ? Close(id_) : 0;
    id_ = H5I_INVALID_HID;
    return status >= 0;
  }

 private:
  void reset() noexcept {
    if (valid()) Close(id_);
    id_ = H5I_INVALID_HID;
  }

  hid_t id_ = H5I_INVALID_HID;
};

using File = Handle<H5Fclose>;
using Object = Handle<H5Oclose>;  // any object opened with H5Oopen
using Dataset = Handle<H5Dclose>;
using Dataspace = Handle<H5Sclose>;
using Datatype = Handle<H5Tclose>;
using Attribute = Handle<H5Aclose>;
using PropertyList = Handle<H5Pclose>;

// Turns off HDF5's automatic printing of its error stack for the guard's
// lifetime and restores the caller's setting afterwards: the library never
// prints, and an application that wants HDF5's diagnostics keeps them.
// Declare it before any Handle so it outlives their closing.
class ErrorPrintingOff {
 public:
  ErrorPrintingOff() {
    if (H5Eget_auto2(H5E_DEFAULT, &function_, &client_data_) < 0) {
      function_ = nullptr;
      client_data_ = nullptr;
    }
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ErrorPrintingOff(const ErrorPrintingOff&) = delete;
  ErrorPrintingOff& operator=(const ErrorPrintingOff&) = delete;
  ~ErrorPrintingOff() {
    if (restore_) H5Eset_auto2(H5E_DEFAULT, function_, client_data_);
  }

  // Leaves printing off for good. A damaged file can leave HDF5 unable to
  // close its internals, and at exit it then prints "HDF5: infinite loop
  // closing library" and a line of interface names, unless printing is off.
  void keep_off() { restore_ = false; }

 private:
  H5E_auto2_t function_ = nullptr;
  void* client_data_ = nullptr;
  bool restore_ = true;
};

// The most specific entry of HDF5's current error stack, shortened to the
// operating-system message when HDF5 quotes one ("No space left on device").
// Call it right after the failing call: any later HDF5 call clears the stack.
inline std::string error_reason() {
  std::string innermost;
  const auto take_first = [](unsigned n, const H5E_error2_t* error, void* data) -> herr_t {
    if (n == 0 && error->desc != nullptr) *static_cast<std::string*>(data) = error->desc;
    return 0;
  };
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, take_first, &innermost);
  if (innermost.empty()) return "unknown HDF5 error";
  const std::string marker = "error message = '";
  const std::size_t begin = innermost.find(marker);
  if (begin != std::string::npos) {
    const std::size_t text = begin + marker.size();
    const std::size_t end = innermost.find('\'', text);
    if (end != std::string::npos && end > text) return innermost.substr(text, end - text);
  }
  return innermost;
}

}  // namespace halfspace::io::detail
