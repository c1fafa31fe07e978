#include "io/hdf5_handle.hpp"

#include <stdexcept>

namespace isphdem::h5 {

QuietErrors::QuietErrors() {
  H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

QuietErrors::~QuietErrors() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }

namespace {

struct Messages {
  std::string outer, inner;
};

herr_t collect(unsigned n, const H5E_error2_t* e, void* data) {
  auto* m = static_cast<Messages*>(data);
  std::string text =
      std::string(e->func_name ? e->func_name : "?") + ": " + (e->desc ? e->desc : "");
  if (n == 0) m->outer = text;
  m->inner = text;
  return 0;
}

}  // namespace

std::string error_text() {
  Messages m;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, collect, &m);
  H5Eclear2(H5E_DEFAULT);
  if (m.outer.empty()) return "no HDF5 error message";
  return m.outer == m.inner ? m.outer : m.outer + "; " + m.inner;
}

void check(herr_t status, const std::string& context, const std::string& what) {
  if (status < 0) throw std::runtime_error(context + ": " + what + " (" + error_text() + ")");
}

Handle::Handle(hid_t id, Closer close, const std::string& context, const std::string& what)
    : id_(id), close_(close) {
  if (id_ < 0) throw std::runtime_error(context + ": " + what + " (" + error_text() + ")");
}

Handle::~Handle() {
  if (id_ >= 0) close_(id_);
}

void Handle::close(const std::string& context, const std::string& what) {
  const hid_t id = id_;
  id_ = -1;
  check(close_(id), context, what);
}

}  // namespace isphdem::h5
