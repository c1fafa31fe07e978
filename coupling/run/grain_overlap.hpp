// The deepest overlap between two grains, as a fraction of the smaller radius: the sign that the
// DEM step is too long for the contact stiffness. A soft-sphere contact that resolves its
// collision overlaps by a small fraction of a radius (the seed's k = 25000 N/m holds 1 mm grains
// at about 1e-6 of their radius under their own weight); grains that pass through each other in
// one DEM step are a failed run, however calm the fluid looks. Spheres of one clump overlap by
// design and are not compared.
#ifndef ISPHDEM_RUN_GRAIN_OVERLAP_HPP
#define ISPHDEM_RUN_GRAIN_OVERLAP_HPP

#include "dem_state.hpp"

namespace isphdem {

struct GrainOverlap {
  double relative = 0.0;  // (r_a + r_b - |x_a - x_b|) / min(r_a, r_b); 0 when nothing touches
  int tag_a = -1, tag_b = -1;
};

// Over all pairs of atoms not in the same body, by a cell list (O(N)). Pairs across a periodic
// boundary of the DEM box are not seen (DemState does not carry the box).
GrainOverlap deepest_overlap(const DemState& state);

// The overlap beyond which a coupled run stops (cause "grain_overlap"): a fifth of a radius is
// thousands of times what any load in these scenes presses into a contact.
constexpr double kMaxGrainOverlap = 0.2;

}  // namespace isphdem

#endif
