// What the fluid side reads from the DEM side once per fluid step (DESIGN.md, key decision 2).
// SI units. Rows are sorted by tag (atoms) and by id (bodies), so the state is the same on every
// rank and for any number of ranks.
#ifndef ISPHDEM_DEM_STATE_HPP
#define ISPHDEM_DEM_STATE_HPP

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace isphdem {

using Vec3 = std::array<double, 3>;
using Quat = std::array<double, 4>;  // (w, x, y, z), body principal frame -> space
using Mat3 = std::array<Vec3, 3>;    // row-major

inline double norm(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

struct DemAtom {
  int tag = 0;
  Vec3 x{}, v{}, omega{};
  double radius = 0.0;
  int body = -1;  // id of the multisphere body this sphere belongs to, -1 for a free sphere
};

struct DemBody {
  int id = 0;
  Vec3 x{}, v{}, omega{};  // centre of mass, its velocity, angular velocity (space frame)
  Quat quat{1.0, 0.0, 0.0, 0.0};
  double mass = 0.0, volume = 0.0;
  Vec3 inertia{};            // principal moments
  Mat3 axes{};               // principal axes in the space frame: axes[k] belongs to inertia[k]
  std::vector<int> members;  // tags of the atoms of this body, ascending

  // Inertia tensor in the space frame: sum_k inertia[k] axes[k] axes[k]^T.
  Mat3 inertia_tensor() const;
};

struct DemState {
  std::int64_t step = 0;  // DEM time step counter
  double time = 0.0;      // DEM time advanced since initialize() returned
  std::vector<DemAtom> atoms;
  std::vector<DemBody> bodies;
};

}  // namespace isphdem

#endif
