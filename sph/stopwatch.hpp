#pragma once
// Accumulates wall-clock seconds into one timing bucket for the scope it lives in.
#include <omp.h>

namespace isph {

class Stopwatch {
 public:
  explicit Stopwatch(double& bucket) : bucket_(bucket), t0_(omp_get_wtime()) {}
  ~Stopwatch() { bucket_ += omp_get_wtime() - t0_; }
  Stopwatch(const Stopwatch&) = delete;
  Stopwatch& operator=(const Stopwatch&) = delete;

 private:
  double& bucket_;
  double t0_;
};

}  // namespace isph
