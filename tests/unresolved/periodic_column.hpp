// The seepage column of the fixed-bed tests (test_porous_bed, test_mean_flow_drive): water in a
// 2D column periodic in x and y, 8 mm x 70 mm at dx = 1 mm, moving up at U, with a bed of
// porosity 0.4 from 20 to 50 mm; the solver's body force along y is `drive`.
#pragma once

#include <utility>

#include "isph_solver.hpp"
#include "lattice.hpp"

namespace isphdem::column {

constexpr double kDx = 1e-3, kRho = 1000.0, kNu = 1e-6;
constexpr double kBedLo = 0.020, kBedHi = 0.050, kHeight = 0.070, kWidth = 0.008;

inline isph::IsphSolver<2> make_solver(double U, double drive) {
  isph::Domain<2> domain;
  domain.lo = {0.0, 0.0};
  domain.hi = {kWidth, kHeight};
  domain.periodic = {true, true};
  isph::Particles<2> P;
  P.spacing = kDx;
  P.volume = kDx * kDx;
  isph::fill_box<2>(P, domain.lo, domain.hi, kDx, isph::kFluid);
  for (auto& v : P.v) v = {0.0, U};
  isph::IsphConfig<2> cfg;
  cfg.density = kRho;
  cfg.viscosity = kNu;
  cfg.free_surface = false;
  cfg.gravity = {0.0, drive};
  return isph::IsphSolver<2>(cfg, domain, std::move(P));
}

}  // namespace isphdem::column
