#pragma once
// Numbers and vectors in error messages: short, with the given significant digits.
#include <sstream>
#include <string>

namespace isph {

inline std::string format_number(double v, int digits = 6) {
  std::ostringstream s;
  s.precision(digits);
  s << v;
  return s.str();
}

// Positions in error messages: (x, y[, z]), 6 significant digits.
template <class V>
std::string format_vector(const V& v) {
  std::ostringstream s;
  s.precision(6);
  s << "(";
  for (int a = 0; a < static_cast<int>(v.size()); ++a) s << (a ? ", " : "") << v[a];
  s << ")";
  return s.str();
}

}  // namespace isph
