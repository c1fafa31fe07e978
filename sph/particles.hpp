#pragma once
// Structure-of-arrays particle storage. Every per-particle array is listed in for_each_array so
// that re-sorting (for cache locality) and appending can never forget one, nor a checkpoint (which
// names each: coupling/run/fluid_checkpoint.cpp, refusing to write when one is new to it).
#include <cstdint>
#include <vector>

#include "vec.hpp"

namespace isph {

// Values are part of the output contract (/fluid/kind).
enum Kind : int32_t { kFluid = 0, kWall = 1, kSolid = 2, kForcing = 3 };

template <int Dim>
struct Particles {
  std::vector<Vec<Dim>> x;       // position [m]
  std::vector<Vec<Dim>> v;       // (Darcy) velocity [m/s]; prescribed velocity for walls/solids
  std::vector<double> p;         // pressure [Pa]
  std::vector<double> porosity;  // fluid volume fraction, 1 in clear fluid
  // Porous terms (seed Eq. (2)), set by the coupling before each step (sph/porous_medium.hpp):
  // velocity of the solid phase and resistance coefficient K [1/s] of F_r* = -K (v_D/eps - v_s).
  std::vector<Vec<Dim>> solid_velocity;
  std::vector<double> resistance;
  std::vector<int32_t> kind;     // Kind
  std::vector<int64_t> id;       // stable identity across re-sorting
  std::vector<uint8_t> surface;  // 1 where the free-surface condition p = 0 applies
  // Wall and solid particles: unit normal of the nearest wall surface pointing into the fluid,
  // and the distance to that surface (zero normal: unknown, the plain Adami mirror is used).
  std::vector<Vec<Dim>> normal;
  std::vector<double> wall_distance;
  // PMS solids (kind kSolid, sph/rigid_solids.hpp): rigid body index (-1 otherwise), position in
  // the body frame, the outward surface normal in the body frame (zero deep inside), and the
  // fluid force on the particle in the last step (N; per unit depth in 2D).
  std::vector<int32_t> body;
  std::vector<Vec<Dim>> body_offset;
  std::vector<Vec<Dim>> body_normal;
  std::vector<Vec<Dim>> solid_force;

  double volume = 0.0;   // particle volume dx^Dim (uniform spacing)
  double spacing = 0.0;  // dx
  int64_t next_id = 0;
  // A scene built on several processes at once, each keeping only its share (so that none holds
  // the whole): add() numbers every particle but stores only those whose id is keep_part modulo
  // keep_parts. Each process then holds the particles IsphSolver::decompose would have kept of
  // the whole scene, with the same ids.
  int64_t keep_part = 0, keep_parts = 1;

  std::size_t size() const { return x.size(); }

  // Appends one particle with the next free id (unless not this process's share, above).
  void add(const Vec<Dim>& pos, const Vec<Dim>& vel, int32_t k);

  // Reorders every array so that new index n holds old index perm[n].
  void permute(const std::vector<int>& perm);

  std::size_t count(int32_t k) const;

  template <class F>
  void for_each_array(F&& f) {
    f(x);
    f(v);
    f(p);
    f(porosity);
    f(solid_velocity);
    f(resistance);
    f(kind);
    f(id);
    f(surface);
    f(normal);
    f(wall_distance);
    f(body);
    f(body_offset);
    f(body_normal);
    f(solid_force);
  }
};

}  // namespace isph
