// Every key a case file for `isphdem run` may hold: fluid scene, run settings, [dem],
// [unresolved] and [coupling]. Case files are checked against it (CaseFile::load), so tests and
// benchmarks that load the shipped examples accept exactly what the driver accepts.
#ifndef ISPHDEM_CASE_KEYS_HPP
#define ISPHDEM_CASE_KEYS_HPP

#include <string>
#include <vector>

namespace isphdem {

std::vector<std::string> case_keys();

}  // namespace isphdem

#endif
