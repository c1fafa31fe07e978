#pragma once
// Amplitude of the Taylor-Green mode in a particle velocity field: the least-squares projection
// onto the unit-amplitude mode at the particles' current positions (robust to disorder, unlike
// max |u|).
#include <cmath>

#include "particles.hpp"

namespace isphdem::validation {

inline double taylor_green_amplitude(const isph::Particles<2>& p, double L) {
  const double k = 2.0 * M_PI / L;
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != isph::kFluid) continue;
    const double x = p.x[i][0], y = p.x[i][1];
    const double ux = -std::cos(k * x) * std::sin(k * y), uy = std::sin(k * x) * std::cos(k * y);
    num += p.v[i][0] * ux + p.v[i][1] * uy;
    den += ux * ux + uy * uy;
  }
  return num / den;
}

}  // namespace isphdem::validation
