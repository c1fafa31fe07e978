#include "fix_couple_isph.h"

#include <mpi.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "fix_multisphere.h"
#include "memory.h"
#include "modify.h"
#include "multisphere.h"
#include "planar_constraint.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {

constexpr int kLoadCols = 6;  // force xyz, torque xyz; exposed as f_ID[1..6] for dumps

// A body's force and torque container, reset by fix multisphere in pre_force on every step.
double** body_torque_array(Multisphere& ms) { return ms.extract_double_vector("torque"); }
double** body_force_array(Multisphere& ms) { return ms.extract_double_vector("fcm"); }

}  // namespace

FixCoupleIsph::FixCoupleIsph(LAMMPS* lmp, int narg, char** arg) : Fix(lmp, narg, arg) {
  for (int iarg = 3; iarg < narg;) {
    if (std::strcmp(arg[iarg], "planar") == 0) {
      if (iarg + 3 > narg)
        error->fix_error(FLERR, this,
                         "keyword 'planar' needs an axis and a coordinate: "
                         "planar x|y|z COORD");
      const char* axis = arg[iarg + 1];
      if (std::strlen(axis) != 1 || axis[0] < 'x' || axis[0] > 'z')
        error->fix_error(FLERR, this, "'planar' axis must be x, y or z (the slab normal)");
      char* end = nullptr;
      plane_coord_ = std::strtod(arg[iarg + 2], &end);
      if (end == arg[iarg + 2] || *end != '\0' || !std::isfinite(plane_coord_))
        error->fix_error(FLERR, this, "'planar' coordinate must be a number (slab mid-plane)");
      planar_ = true;
      normal_ = axis[0] - 'x';
      iarg += 3;
    } else {
      std::string msg =
          std::string("unknown keyword '") + arg[iarg] + "' (known keywords: planar x|y|z COORD)";
      error->fix_error(FLERR, this, msg.c_str());
    }
  }

  create_attribute = 1;  // new (inserted) atoms start with zero load
  // Existing atoms are zeroed below; without this the first run's setup would zero them again
  // and drop loads set between the fix's creation and that run.
  just_created = 0;
  peratom_flag = 1;
  size_peratom_cols = kLoadCols;
  peratom_freq = 1;
  nevery = 1;  // end_of_step on every step (planar velocity projection)

  grow_arrays(atom->nmax);
  atom->add_callback(0);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
}

FixCoupleIsph::~FixCoupleIsph() {
  atom->delete_callback(id, 0);
  memory->destroy(hload_);
}

int FixCoupleIsph::setmask() {
  // PRE_FORCE only so that setup_pre_force is called; pre_force itself is a no-op.
  int mask = PRE_FORCE | POST_FORCE;
  if (planar_) mask |= POST_INTEGRATE | END_OF_STEP;
  return mask;
}

void FixCoupleIsph::init() {
  if (atom->map_style == 0)
    error->fix_error(FLERR, this,
                     "loads are keyed by atom tag and need an atom map: add "
                     "'atom_modify map array' before the simulation box is created");
  if (!atom->tag_enable) error->fix_error(FLERR, this, "needs atom IDs (atom_modify id yes)");
  if (!atom->torque_flag || !atom->omega_flag)
    error->fix_error(FLERR, this, "needs per-atom omega and torque (atom_style sphere)");
  find_multisphere();
}

void FixCoupleIsph::find_multisphere() {
  ms_ = nullptr;
  for (int i = 0; i < modify->nfix && !ms_; i++)
    ms_ = dynamic_cast<FixMultisphere*>(modify->fix[i]);
}

void FixCoupleIsph::add_atom_loads() {
  double** f = atom->f;
  double** torque = atom->torque;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    for (int k = 0; k < 3; k++) {
      f[i][k] += hload_[i][k];
      torque[i][k] += hload_[i][3 + k];
    }
  }
}

bool FixCoupleIsph::is_free_grain(int i) const {
  return (atom->mask[i] & groupbit) && !(ms_ && ms_->belongs_to(i) >= 0);
}

// Atom loads go in here, before the pair forces and before fix multisphere's setup() sums atom
// forces into its bodies, so that the setup forces include them whatever the fix order.
void FixCoupleIsph::setup_pre_force(int) {
  if (!ms_) find_multisphere();
  add_atom_loads();
}

// Body loads go in here: fix multisphere's setup() adds to, never resets, the body force.
void FixCoupleIsph::setup(int) {
  add_body_loads();
  if (planar_) {
    apply_planar_to_bodies(true);
    apply_planar_to_forces();
    apply_planar_to_velocities(true);
  }
}

void FixCoupleIsph::post_force(int) {
  add_atom_loads();
  add_body_loads();
  if (planar_) {
    apply_planar_to_bodies(false);  // bodies inserted during the run get their flags here
    apply_planar_to_forces();
  }
}

// After every fix's initial_integrate: whatever another fix added out of plane is undone
// before forces are computed, so contacts always see in-plane positions.
void FixCoupleIsph::post_integrate() { apply_planar_to_velocities(true); }

void FixCoupleIsph::end_of_step() { apply_planar_to_velocities(false); }

void FixCoupleIsph::add_body_loads() {
  if (!ms_ || body_force_.empty()) return;
  Multisphere& ms = ms_->data();
  double** torque = body_torque_array(ms);
  for (int ib = 0; ib < ms.n_body(); ib++) {
    const int tag = ms.tag(ib);
    if (tag < 0 || tag >= static_cast<int>(body_slot_.size()) || body_slot_[tag] < 0) continue;
    const int s = body_slot_[tag];
    ms.add_external_force(body_force_[s].data(), ib);
    for (int k = 0; k < 3; k++) torque[ib][k] += body_torque_[s][k];
  }
}

// Adds a load change to the body force/torque that fix multisphere's next initial_integrate
// uses, if this rank owns the body. A member atom's force acts at x_unwrapped; a body load
// (x_unwrapped null) at the centre of mass.
void FixCoupleIsph::add_to_body(int body_tag, const double* df, const double* dt,
                                const double* x_unwrapped) {
  Multisphere& ms = ms_->data();
  if (body_tag < 0 || body_tag > ms.tag_max_body()) return;
  const int ib = ms.map(body_tag);
  if (ib < 0) return;
  double** fcm = body_force_array(ms);
  double** tcm = body_torque_array(ms);
  double r[3] = {0.0, 0.0, 0.0};
  if (x_unwrapped) {
    double xcm[3];
    ms.xcm(xcm, ib);
    for (int k = 0; k < 3; k++) r[k] = x_unwrapped[k] - xcm[k];
  }
  fcm[ib][0] += df[0];
  fcm[ib][1] += df[1];
  fcm[ib][2] += df[2];
  tcm[ib][0] += r[1] * df[2] - r[2] * df[1] + dt[0];
  tcm[ib][1] += r[2] * df[0] - r[0] * df[2] + dt[1];
  tcm[ib][2] += r[0] * df[1] - r[1] * df[0] + dt[2];
}

int FixCoupleIsph::set_atom_loads(int n, const int* tags, const double* force,
                                  const double* torque) {
  const int nlocal = atom->nlocal;
  std::vector<double> next(static_cast<size_t>(nlocal) * kLoadCols, 0.0);
  int owned = 0;
  for (int k = 0; k < n; k++) {
    const int i = atom->map(tags[k]);
    if (i < 0 || i >= nlocal || !(atom->mask[i] & groupbit)) continue;
    for (int c = 0; c < 3; c++) {
      next[i * kLoadCols + c] = force[3 * k + c];
      next[i * kLoadCols + 3 + c] = torque[3 * k + c];
    }
    owned++;
  }

  // The forces left from the last step are what the next step's first half-kick uses: correct
  // them by the change. Free grains directly; clump members through their body, whose owner
  // may be another rank, so their changes are shared (body tag, dF, dT, unwrapped position).
  if (!ms_) find_multisphere();
  std::vector<double> member_changes;
  double** f = atom->f;
  double** tq = atom->torque;
  for (int i = 0; i < nlocal; i++) {
    double d[kLoadCols];
    bool changed = false;
    for (int c = 0; c < kLoadCols; c++) {
      d[c] = next[i * kLoadCols + c] - hload_[i][c];
      changed |= d[c] != 0.0;
      hload_[i][c] = next[i * kLoadCols + c];
    }
    if (!changed) continue;
    const int body = ms_ ? ms_->belongs_to(i) : -1;
    if (body < 0) {
      if (planar_) planar::project_load(normal_, d, d + 3);
      for (int c = 0; c < 3; c++) {
        f[i][c] += d[c];
        tq[i][c] += d[3 + c];
      }
    } else {
      double xu[3];
      domain->unmap(atom->x[i], atom->image[i], xu);
      member_changes.push_back(body);
      member_changes.insert(member_changes.end(), d, d + kLoadCols);
      member_changes.insert(member_changes.end(), xu, xu + 3);
    }
  }
  if (ms_) {
    constexpr int kRec = 1 + kLoadCols + 3;
    int nprocs = 1;
    MPI_Comm_size(world, &nprocs);
    int mine = static_cast<int>(member_changes.size());
    std::vector<int> counts(nprocs), displs(nprocs, 0);
    MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
    for (int p = 1; p < nprocs; p++) displs[p] = displs[p - 1] + counts[p - 1];
    std::vector<double> all(displs[nprocs - 1] + counts[nprocs - 1]);
    MPI_Allgatherv(member_changes.data(), mine, MPI_DOUBLE, all.data(), counts.data(),
                   displs.data(), MPI_DOUBLE, world);
    for (size_t r = 0; r + kRec <= all.size(); r += kRec)
      add_to_body(static_cast<int>(all[r]), &all[r + 1], &all[r + 4], &all[r + 7]);
  }
  return owned;
}

int FixCoupleIsph::set_body_loads(int n, const int* body_tags, const double* force,
                                  const double* torque) {
  int max_tag = -1;
  for (int k = 0; k < n; k++) max_tag = std::max(max_tag, body_tags[k]);
  std::vector<int> slot(max_tag + 1, -1);
  std::vector<Vec3> bf(n), bt(n);
  for (int k = 0; k < n; k++) {
    if (body_tags[k] < 0) continue;
    slot[body_tags[k]] = k;
    for (int c = 0; c < 3; c++) {
      bf[k][c] = force[3 * k + c];
      bt[k][c] = torque[3 * k + c];
    }
  }

  // As for atoms: correct the body force of the last step by the change (see set_atom_loads).
  int owned = 0;
  if (!ms_) find_multisphere();
  if (ms_) {
    Multisphere& ms = ms_->data();
    auto lookup = [](const std::vector<int>& slots, int tag) {
      return tag >= 0 && tag < static_cast<int>(slots.size()) ? slots[tag] : -1;
    };
    for (int ib = 0; ib < ms.n_body(); ib++) {
      const int tag = ms.tag(ib);
      const int s_new = lookup(slot, tag), s_old = lookup(body_slot_, tag);
      if (s_new >= 0) owned++;
      double df[3] = {0, 0, 0}, dt[3] = {0, 0, 0};
      for (int c = 0; c < 3; c++) {
        if (s_new >= 0) df[c] += bf[s_new][c], dt[c] += bt[s_new][c];
        if (s_old >= 0) df[c] -= body_force_[s_old][c], dt[c] -= body_torque_[s_old][c];
      }
      add_to_body(tag, df, dt, nullptr);
    }
  }
  body_slot_ = std::move(slot);
  body_force_ = std::move(bf);
  body_torque_ = std::move(bt);
  return owned;
}

void FixCoupleIsph::apply_planar_to_forces() {
  for (int i = 0; i < atom->nlocal; i++)
    if (is_free_grain(i)) planar::project_load(normal_, atom->f[i], atom->torque[i]);
}

void FixCoupleIsph::apply_planar_to_velocities(bool snap_positions) {
  for (int i = 0; i < atom->nlocal; i++) {
    if (!is_free_grain(i)) continue;
    planar::project_motion(normal_, atom->v[i], atom->omega[i]);
    if (snap_positions) atom->x[i][normal_] = plane_coord_;
  }
}

void FixCoupleIsph::apply_planar_to_bodies(bool collective) {
  if (!ms_) return;
  const int bad_tag = planar::constrain_bodies(ms_->data(), normal_, plane_coord_);
  // A tilted clump would be turned out of plane by any in-plane torque: refuse it.
  auto message = [&](int tag) {
    return "planar: multisphere body " + std::to_string(tag) +
           " has no principal axis along the slab normal (its spheres do not lie in one plane "
           "parallel to the slab, or its inertia tensor from Monte Carlo is not exact); give the "
           "template 'mass ... inertia_tensor ...' with zero out-of-plane products and insert "
           "with 'orientation template'";
  };
  if (collective) {
    int mine = bad_tag < 0 ? INT_MAX : bad_tag, first_bad = INT_MAX;
    MPI_Allreduce(&mine, &first_bad, 1, MPI_INT, MPI_MIN, world);
    if (first_bad != INT_MAX) error->fix_error(FLERR, this, message(first_bad).c_str());
  } else if (bad_tag >= 0) {
    // Mid-run (a body inserted during the run): no collective call is possible here.
    const std::string msg = std::string("Fix couple/isph (id ") + id + "): " + message(bad_tag);
    std::fprintf(stderr, "ERROR: %s\n", msg.c_str());
    error->one(FLERR, msg.c_str());
  }
}

void FixCoupleIsph::grow_arrays(int nmax) {
  memory->grow(hload_, nmax, kLoadCols, "couple/isph:hload");
  array_atom = hload_;
}

void FixCoupleIsph::copy_arrays(int i, int j, int) {
  for (int c = 0; c < kLoadCols; c++) hload_[j][c] = hload_[i][c];
}

void FixCoupleIsph::set_arrays(int i) {
  for (int c = 0; c < kLoadCols; c++) hload_[i][c] = 0.0;
}

int FixCoupleIsph::pack_exchange(int i, double* buf) {
  for (int c = 0; c < kLoadCols; c++) buf[c] = hload_[i][c];
  return kLoadCols;
}

int FixCoupleIsph::unpack_exchange(int nlocal, double* buf) {
  for (int c = 0; c < kLoadCols; c++) hload_[nlocal][c] = buf[c];
  return kLoadCols;
}

double FixCoupleIsph::memory_usage() {
  return static_cast<double>(atom->nmax) * kLoadCols * sizeof(double);
}
