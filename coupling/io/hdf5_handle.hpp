// Checked HDF5 C API calls: every id is owned by a Handle (closed on scope exit, so an exception
// halfway through a file leaks nothing), and a failing call throws std::runtime_error carrying
// HDF5's own explanation instead of letting HDF5 print its error stack to stderr.
#pragma once

#include <hdf5.h>

#include <string>

namespace isphdem::h5 {

// While alive, HDF5 keeps its error stack to itself (it is read into the exception instead).
class QuietErrors {
 public:
  QuietErrors();
  ~QuietErrors();
  QuietErrors(const QuietErrors&) = delete;
  QuietErrors& operator=(const QuietErrors&) = delete;

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

// The current HDF5 error stack, outermost and innermost message ("" if empty).
std::string error_text();

// Throws std::runtime_error("<context>: <what> (<HDF5 message>)") if status < 0.
void check(herr_t status, const std::string& context, const std::string& what);

class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle(hid_t id, Closer close, const std::string& context, const std::string& what);
  ~Handle();
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  hid_t id() const { return id_; }
  // Closes now and throws if that fails (closing a file flushes it, so this is where a full disk
  // shows up).
  void close(const std::string& context, const std::string& what);

 private:
  hid_t id_;
  Closer close_;
};

}  // namespace isphdem::h5
