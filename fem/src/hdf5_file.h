#pragma once
// What the XDMF writer and reader (export_xdmf.cpp, import_xdmf.cpp) share of the HDF5 C API: a
// handle that closes itself, a guard that keeps HDF5 from printing its error stack (the library
// prints nothing), and the reason HDF5 gives for the last failure, for a one-line message.

#include <hdf5.h>

#include <string>

namespace meshprep::detail {

/// An HDF5 identifier (file, group, dataset, dataspace, property list) closed by `close` when the
/// handle goes; a failed call's negative identifier is held too, so that `valid()` tests it.
class Hdf5Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Hdf5Handle(hid_t id, Closer close) : id_(id), close_(close) {}
  Hdf5Handle(const Hdf5Handle&) = delete;
  Hdf5Handle& operator=(const Hdf5Handle&) = delete;
  ~Hdf5Handle() { close(); }

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  /// Closes now: false if HDF5 reports a failure (for a file: its data could not be written).
  bool close() {
    if (id_ < 0) return true;
    const herr_t status = close_(id_);
    id_ = H5I_INVALID_HID;
    return status >= 0;
  }

 private:
  hid_t id_;
  Closer close_;
};

/// While it lives, HDF5 reports failures to the caller only: its automatic printing of the error
/// stack to stderr is off for this thread (Debian's libhdf5 is thread-safe, where the setting is
/// per thread), and set back as it was afterwards.
class Hdf5Quiet {
 public:
  Hdf5Quiet();
  Hdf5Quiet(const Hdf5Quiet&) = delete;
  Hdf5Quiet& operator=(const Hdf5Quiet&) = delete;
  ~Hdf5Quiet();

 private:
  H5E_auto2_t function_ = nullptr;
  void* data_ = nullptr;
};

/// The reason of the innermost failure on this thread's HDF5 error stack: the system's message
/// when HDF5 quotes one ("No space left on device"), else HDF5's own description; empty if none.
std::string hdf5_reason();

}  // namespace meshprep::detail
