#include "io/atomic_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

namespace isphdem {

namespace fs = std::filesystem;

fs::path temporary_path_for(const fs::path& target) {
  return target.parent_path() / ("." + target.filename().string() + ".tmp");
}

bool is_temporary_name(std::string_view name) {
  constexpr std::string_view suffix = ".tmp";
  return name.size() > 1 + suffix.size() && name.front() == '.' &&
         name.substr(name.size() - suffix.size()) == suffix;
}

void write_file_atomically(const fs::path& target, std::string_view contents) {
  const fs::path tmp = temporary_path_for(target);
  auto fail = [&](const std::string& what, int err) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw std::runtime_error(what + " " + tmp.string() + ": " + std::strerror(err));
  };
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) fail("cannot create", errno);
  const bool written = std::fwrite(contents.data(), 1, contents.size(), f) == contents.size();
  const int write_errno = errno;
  // fclose flushes, so its result decides whether the data reached the kernel.
  const bool closed = std::fclose(f) == 0;
  if (!written) fail("cannot write", write_errno);
  if (!closed) fail("cannot write", errno);
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw std::runtime_error("cannot rename " + tmp.string() + " to " + target.string() + ": " +
                             ec.message());
  }
}

}  // namespace isphdem
