#include "planar_constraint.h"

#include <algorithm>
#include <cmath>

#include "multisphere.h"

namespace planar {

namespace {

// A principal axis within this angle (radians) of the normal keeps clump atoms in plane to
// well below 1e-12 m for mm-sized clumps over long runs.
constexpr double kMaxTilt = 1e-10;

}  // namespace

void project_load(int normal, double* force, double* torque) {
  force[normal] = 0.0;
  for (int k = 0; k < 3; k++)
    if (k != normal) torque[k] = 0.0;
}

void project_motion(int normal, double* v, double* omega) { project_load(normal, v, omega); }

int constrain_bodies(LAMMPS_NS::Multisphere& ms, int normal, double plane_coord) {
  double** xcm = ms.extract_double_vector("xcm");
  double** vcm = ms.extract_double_vector("vcm");
  double** omega = ms.extract_double_vector("omega");
  double** angmom = ms.extract_double_vector("angmom");
  double** axes[3] = {ms.extract_double_vector("ex_space"), ms.extract_double_vector("ey_space"),
                      ms.extract_double_vector("ez_space")};
  bool fflag[3] = {true, true, true}, tflag[3] = {false, false, false};
  fflag[normal] = false;
  tflag[normal] = true;

  int bad_tag = -1;
  for (int ib = 0; ib < ms.n_body(); ib++) {
    ms.set_fflag(ib, fflag);
    ms.set_tflag(ib, tflag);
    vcm[ib][normal] = 0.0;
    xcm[ib][normal] = plane_coord;

    bool spins_out_of_plane = false;
    for (int k = 0; k < 3; k++)
      if (k != normal && (omega[ib][k] != 0.0 || angmom[ib][k] != 0.0)) spins_out_of_plane = true;
    if (spins_out_of_plane) {
      double w[3] = {0.0, 0.0, 0.0};
      w[normal] = omega[ib][normal];
      ms.set_angmom_via_omega_body(ib, w);
    }

    // Tilt of the principal axis closest to the normal, from its in-plane components.
    double** e = axes[0];
    for (auto& a : axes)
      if (std::fabs(a[ib][normal]) > std::fabs(e[ib][normal])) e = a;
    double tilt2 = 0.0;
    for (int k = 0; k < 3; k++)
      if (k != normal) tilt2 += e[ib][k] * e[ib][k];
    if (std::sqrt(tilt2) > kMaxTilt && bad_tag < 0) bad_tag = ms.tag(ib);
  }
  return bad_tag;
}

}  // namespace planar
