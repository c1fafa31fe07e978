// fix couple/isph: hands hydrodynamic loads from the ISPH fluid to LIGGGHTS grains and clumps.
//
//   fix ID group couple/isph [planar x|y|z COORD]
//
// Per-atom loads are stored in per-atom arrays that migrate with their atoms; per-body loads
// (multisphere clumps) are kept by body tag on every rank, because bodies migrate inside fix
// multisphere where no callback reaches them. Both are added on every DEM step in post_force.
// Registered at run time (register_couple_isph.h), not through LIGGGHTS's compiled style table.
#ifndef ISPHDEM_FIX_COUPLE_ISPH_H
#define ISPHDEM_FIX_COUPLE_ISPH_H

#include <array>
#include <vector>

#include "fix.h"

namespace LAMMPS_NS {

class FixMultisphere;

class FixCoupleIsph : public Fix {
 public:
  static constexpr const char* kStyle = "couple/isph";

  FixCoupleIsph(LAMMPS* lmp, int narg, char** arg);
  ~FixCoupleIsph() override;

  int setmask() override;
  void init() override;
  void setup_pre_force(int vflag) override;
  void setup(int vflag) override;
  void post_integrate() override;
  void post_force(int vflag) override;
  void end_of_step() override;

  void grow_arrays(int nmax) override;
  void copy_arrays(int i, int j, int delflag) override;
  void set_arrays(int i) override;
  int pack_exchange(int i, double* buf) override;
  int unpack_exchange(int nlocal, double* buf) override;
  double memory_usage() override;

  // Replaces all per-atom loads (atoms not listed get zero). Collective; every rank passes the
  // same list. The forces of the current step are corrected by the change, so the new loads act
  // from the next step's first half-kick on: a load set before `run N` acts over exactly N steps.
  // Returns the number of listed tags owned by this rank and in the fix group.
  int set_atom_loads(int n, const int* tags, const double* force, const double* torque);

  // Replaces all per-body loads (force at the centre of mass, torque about it). Collective, same
  // list on every rank. Returns the number of listed bodies owned by this rank.
  int set_body_loads(int n, const int* body_tags, const double* force, const double* torque);

  // Current load of local atom i: force xyz then torque xyz.
  const double* atom_load(int i) const { return hload_[i]; }

  FixMultisphere* multisphere() const { return ms_; }

 private:
  using Vec3 = std::array<double, 3>;

  void find_multisphere();
  bool is_free_grain(int i) const;  // in group and not a clump member
  void add_atom_loads();
  void add_body_loads();
  void add_to_body(int body_tag, const double* df, const double* dt, const double* x_unwrapped);
  void apply_planar_to_forces();
  void apply_planar_to_velocities(bool snap_positions);
  void apply_planar_to_bodies(bool collective);

  double** hload_ = nullptr;  // per-atom force xyz + torque xyz; migrates with the atom

  // Body loads by body tag (index into the vectors below), replicated on every rank.
  std::vector<int> body_slot_;  // body tag -> slot, -1 if none
  std::vector<Vec3> body_force_, body_torque_;

  FixMultisphere* ms_ = nullptr;

  bool planar_ = false;
  int normal_ = 2;  // axis normal to the slab
  double plane_coord_ = 0.0;
};

}  // namespace LAMMPS_NS

#endif
