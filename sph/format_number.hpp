#pragma once
// Numbers in error messages: short, with the given significant digits.
#include <sstream>
#include <string>

namespace isph {

inline std::string format_number(double v, int digits = 6) {
  std::ostringstream s;
  s.precision(digits);
  s << v;
  return s.str();
}

}  // namespace isph
