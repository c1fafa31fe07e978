#pragma once
// Porosity and mean solid velocity at fluid points from unresolved (fine) grains, and the
// grain–fluid kernel weights that the conservative drag distribution reuses
// (docs/unresolved.md). Templated on the fluid's Dim; instantiated for 2 and 3.
//
// eps(x_a) = max(eps_min, 1 - sum_k V_k W_p(|x_a - x_k|) / T),
// with T = 1 in 3D and T = the slab thickness in 2D: a 2D fluid sees the quasi-2D DEM slab of
// DESIGN.md decision 4, whose grains are 3D spheres in a slab T thick, so their volume is spread
// over area x T. W_p is a kernel of its own smoothing length h_p, usually wider than the fluid
// kernel, so that a field of grains about dx across still gives a smooth porosity.
#include <cstddef>
#include <vector>

#include "kernel.hpp"
#include "vec.hpp"

namespace isphdem {

template <int Dim>
struct Grain {
  int tag = 0;  // LIGGGHTS atom tag: loads are handed back by tag, never by local index
  isph::Vec<Dim> x = isph::Vec<Dim>::Zero();  // centre [m] (in-plane part in 2D)
  isph::Vec<Dim> v = isph::Vec<Dim>::Zero();  // velocity [m/s]
  double radius = 0.0;                        // [m]
  // Always the 3D sphere: in 2D the grains are still LIGGGHTS spheres (decision 4).
  double volume() const;
};

struct PorosityMapSettings {
  double smoothing_length = 0.0;  // h_p [m]; support 2 h_p
  // When > 0, grain k's kernel is max(h_p, smoothing_diameters x d_k) wide: a grain not much
  // smaller than dx then sees its own volume spread over enough water (docs/unresolved.md).
  double smoothing_diameters = 0.0;
  isph::KernelType kernel = isph::KernelType::WendlandC2;
  // 0.25 lies below the densest packing of equal spheres (1 - pi/(3 sqrt 2) = 0.2595) and far
  // below any quasi-2D slab packing (>= 0.395): only kernel overshoot can reach it, and it keeps
  // the Ergun a*(eps) ~ (1-eps)^2/eps^3 within 2x of its value at eps = 0.3.
  double min_porosity = 0.25;
  double slab_thickness = 0.0;  // T [m]; required > 0 for a 2D fluid, ignored in 3D
};

// Compressed rows: fluid point a has entries [offset[a], offset[a+1]) with the grain index
// (into the grains passed to compute), V_k W_p(|x_a - x_k|) [m^3 / m^Dim], and the same times
// r_first / r_k, r_first the radius of the row's first grain: the grain's surface in the kernel
// up to the row's common factor, by which the drag is shared (drag_distribution.hpp). For equal
// grains `surface` equals `weight` to the last bit.
struct GrainWeights {
  std::vector<std::size_t> offset;
  std::vector<std::size_t> grain;
  std::vector<double> weight;
  std::vector<double> surface;
  std::size_t fluid_count() const { return offset.empty() ? 0 : offset.size() - 1; }
};

template <int Dim>
struct PorosityField {
  std::vector<double> porosity;  // floored at min_porosity; exactly 1 where no grain is in range
  // Volume-weighted kernel average of the grain velocities; zero where no grain is in range.
  std::vector<isph::Vec<Dim>> solid_velocity;
  // Local Sauter mean diameter d_32 = sum V_k W / sum (V_k W / d_k) of the grains in range: the
  // diameter whose specific surface 6/d the local mixture has, the one Ergun's law takes for a
  // graded bed (Beetstra, van der Hoef & Kuipers 2007). Zero where no grain is in range; exactly
  // the grains' diameter where they all have one.
  std::vector<double> diameter;
  GrainWeights weights;
  std::size_t floored = 0;  // points whose porosity the floor raised (a diagnostic)
};

template <int Dim>
class PorosityMap {
 public:
  explicit PorosityMap(const PorosityMapSettings& settings);  // throws on bad settings

  PorosityField<Dim> compute(const std::vector<isph::Vec<Dim>>& fluid_x,
                             const std::vector<Grain<Dim>>& grains) const;

  const PorosityMapSettings& settings() const { return settings_; }
  // The smoothing length of a grain of this radius, and the support of the widest kernel of
  // these grains (the base support when there are none).
  double smoothing_length_of(double radius) const;
  double support(const std::vector<Grain<Dim>>& grains) const;
  double support() const { return kernel_.support(); }

 private:
  PorosityMapSettings settings_;
  isph::Kernel<Dim> kernel_;
  double normalisation_;  // T in 2D, 1 in 3D
};

}  // namespace isphdem
