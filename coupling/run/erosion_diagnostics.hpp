// Measurements of the internal-erosion experiment (issue 7, seed section 4), for diagnostics.csv
// of coupled runs. The layer is what the grains occupy at the start: its surface is the highest
// grain top, its footprint the grains' horizontal extent. "Up" is against gravity.
#ifndef ISPHDEM_EROSION_DIAGNOSTICS_HPP
#define ISPHDEM_EROSION_DIAGNOSTICS_HPP

#include <map>
#include <string>
#include <vector>

#include "dem_state.hpp"
#include "particles.hpp"

namespace isphdem {

// Height of the fine-grain bed: the 95th percentile of the grain centres' heights along -g
// (the top of the bed without the few grains thrown up above it), or the largest height when
// there are fewer than 20 grains. NaN without grains.
double bed_height(const DemState& state, const Vec3& up);

struct ErosionMeasures {
  int fines_above = 0;          // free spheres entirely above the initial layer surface
  double fines_above_mass = 0;  // their mass [kg] (grain density x sphere volume)
  // Free spheres carried out of the layer's window: centre beside its initial horizontal extent
  // (over an inner wall in the seed's tank) or below its initial bottom (through the mesh).
  int fines_out_of_window = 0;
  // Largest interstitial fluid speed |v_D| / eps among fluid particles inside the initial layer,
  // divided by the reference speed (v_in).
  double max_pore_speed_ratio = 0;
  // The same speeds' 95th percentile and mean (pore_speed_ratios): the jets' measure that one
  // particle does not decide. The maximum of a few hundred particles' speeds moved by 15% between
  // two realizations of the seed's layer where these moved by 5% (docs/internal_erosion.md).
  double pore_speed_p95_ratio = 0, mean_pore_speed_ratio = 0;
  // Every such particle's ratio: measure() fills it with this process's particles and sets the
  // three from them; decomposed, the caller concatenates the ranks' lists and calls
  // set_pore_speeds() again.
  std::vector<double> pore_speed_ratios;
  double surface_height = 0;         // median over 2 mm columns of the highest grain top [m]
  double skeleton_displacement = 0;  // mean in-plane displacement of the clumps' centres [m]
  // Mean speed of the free spheres and of the clumps' centres [m/s]: how lively the layer is as
  // a whole, where max_grain_speed is one grain's (issue 46 compares time steps with these).
  double mean_fine_speed = 0, mean_clump_speed = 0;
};

// Sorts m.pore_speed_ratios and sets their max, 95th percentile (linear between ranks) and mean
// (all zero when it is empty).
void set_pore_speeds(ErosionMeasures& m);

template <int Dim>
class ErosionDiagnostics {
 public:
  // up: unit vector against gravity (3 components, the fluid's axes first); reference_speed:
  // v_in (1 when the case has none); grain_density for the mass of ejected fines.
  ErosionDiagnostics(const DemState& initial, const Vec3& up, double reference_speed,
                     double grain_density);

  ErosionMeasures measure(const DemState& dem, const isph::Particles<Dim>& fluid) const;

  static std::vector<std::string> columns();
  static std::vector<double> row(const ErosionMeasures& m);

  double initial_surface() const { return surface0_; }
  // The initial layer it measures against (a checkpoint's part: a resumed run starts from later
  // grains); restore() takes what state() gave.
  std::vector<double> state() const;
  void restore(const std::vector<double>& state);

 private:
  double height(const Vec3& x) const { return x[0] * up_[0] + x[1] * up_[1] + x[2] * up_[2]; }
  int across_axis() const;  // horizontal axis of the fluid plane

  Vec3 up_;
  double reference_speed_, grain_density_;
  double surface0_ = 0, bottom0_ = 0;  // initial layer top and bottom (heights)
  double lo0_ = 0, hi0_ = 0;           // initial layer's horizontal extent
  std::map<int, Vec3> body0_;          // initial clump centres by body id
};

}  // namespace isphdem

#endif
