#include "dem/dem_liggghts_backend.hpp"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>

#include "atom.h"
#include "dem/liggghts_restart_redirect.hpp"
#include "domain.h"
#include "fix_couple_isph.h"
#include "fix_multisphere.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"
#include "multisphere.h"
#include "update.h"
#include "write_restart.h"

namespace isphdem {

namespace {

// Every rank's rows, concatenated in rank order, on every rank.
std::vector<double> allgather(MPI_Comm comm, const std::vector<double>& mine) {
  int nprocs = 1;
  MPI_Comm_size(comm, &nprocs);
  int n = static_cast<int>(mine.size());
  std::vector<int> counts(nprocs), displs(nprocs, 0);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  for (int p = 1; p < nprocs; p++) displs[p] = displs[p - 1] + counts[p - 1];
  std::vector<double> all(displs[nprocs - 1] + counts[nprocs - 1]);
  MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE,
                 comm);
  return all;
}

// Rank 0's loads on every rank, flattened for the fix.
struct FlatLoads {
  std::vector<int> ids;
  std::vector<double> force, torque;  // 3 per id
};

FlatLoads broadcast_loads(MPI_Comm comm, int rank, const std::vector<int>& ids,
                          const std::vector<Vec3>& force, const std::vector<Vec3>& torque,
                          const char* what) {
  int n = static_cast<int>(ids.size());
  int sizes_ok = force.size() == ids.size() && torque.size() == ids.size();
  int header[2] = {n, sizes_ok};
  MPI_Bcast(header, 2, MPI_INT, 0, comm);
  if (!header[1])
    throw std::invalid_argument(std::string(what) + ": " + std::to_string(ids.size()) +
                                " ids but " + std::to_string(force.size()) + " forces and " +
                                std::to_string(torque.size()) + " torques");
  FlatLoads out;
  out.ids.resize(header[0]);
  out.force.resize(3 * header[0]);
  out.torque.resize(3 * header[0]);
  if (rank == 0) {
    out.ids = ids;
    for (int k = 0; k < n; k++)
      for (int c = 0; c < 3; c++) {
        out.force[3 * k + c] = force[k][c];
        out.torque[3 * k + c] = torque[k][c];
      }
  }
  MPI_Bcast(out.ids.data(), header[0], MPI_INT, 0, comm);
  MPI_Bcast(out.force.data(), 3 * header[0], MPI_DOUBLE, 0, comm);
  MPI_Bcast(out.torque.data(), 3 * header[0], MPI_DOUBLE, 0, comm);

  std::vector<int> sorted = out.ids;
  std::sort(sorted.begin(), sorted.end());
  auto dup = std::adjacent_find(sorted.begin(), sorted.end());
  if (dup != sorted.end())
    throw std::invalid_argument(std::string(what) + ": id " + std::to_string(*dup) +
                                " is listed twice");
  return out;
}

// Throws naming the first id that no rank owns (owned_here(k) says whether this rank does).
template <typename Owned>
void require_all_owned(MPI_Comm comm, const std::vector<int>& ids, Owned owned_here,
                       const std::string& what) {
  std::vector<int> mine(ids.size()), any(ids.size());
  for (size_t k = 0; k < ids.size(); k++) mine[k] = owned_here(ids[k]) ? 1 : 0;
  MPI_Allreduce(mine.data(), any.data(), static_cast<int>(ids.size()), MPI_INT, MPI_MAX, comm);
  for (size_t k = 0; k < ids.size(); k++)
    if (!any[k]) throw std::invalid_argument(what + " " + std::to_string(ids[k]));
}

}  // namespace

LiggghtsBackend::LiggghtsBackend(std::vector<std::string> liggghts_args, MPI_Comm comm)
    : args_(std::move(liggghts_args)), comm_(comm) {
  MPI_Comm_rank(comm_, &rank_);
}

LiggghtsBackend::~LiggghtsBackend() { finalize(); }

void LiggghtsBackend::initialize(const DemSetup& setup) {
  if (lmp_) throw std::logic_error("LiggghtsBackend::initialize called twice");
  if (!setup.script.empty() &&
      (std::filesystem::is_directory(setup.script) || !std::filesystem::exists(setup.script)))
    throw std::runtime_error("cannot open DEM input script '" + setup.script.string() +
                             "': no such readable file");
  lmp_ = open_liggghts(args_, comm_);
  if (!resume_restart_.empty()) redirect_read_restart(lmp_.get(), resume_restart_);
  set_liggghts_context(lmp_, "script " + setup.script.string());
  if (!setup.script.empty()) {
    const LiggghtsStdoutToScreen to_screen(lmp_);
    lmp_->input->file(setup.script.string().c_str());
  }
  if (!resume_restart_.empty() && redirected_restarts(lmp_.get()) == 0)
    throw std::runtime_error(
        "--resume: the DEM script " + setup.script.string() +
        " reads no restart (read_restart), so its grains cannot start from the checkpoint's: a "
        "coupled case resumes when its script builds the grains from a read_restart (as "
        "examples/internal_erosion_2d/in.liggghts does)");
  set_liggghts_context(lmp_, "a command isphdem gave after the script");
  for (const auto& c : setup.commands) command(c);
  set_liggghts_context(lmp_, "the DEM substeps of a fluid step");
  ran_ = false;
  state_.time = resume_restart_.empty() ? 0.0 : resume_time_;
  state_stale_ = true;
}

void LiggghtsBackend::command(const std::string& line) {
  {
    const LiggghtsStdoutToScreen to_screen(lmp_);
    lmp_->input->one(line.c_str());
  }
  state_stale_ = true;
  if (line.rfind("run ", 0) == 0) ran_ = true;
}

double LiggghtsBackend::timestep() const { return lmp_->update->dt; }

void LiggghtsBackend::advance(int n_substeps) {
  if (n_substeps < 1) throw std::invalid_argument("advance: n_substeps must be >= 1");
  const double dt = timestep();
  command("run " + std::to_string(n_substeps) + " pre no post no");
  state_.time += n_substeps * dt;
}

void LiggghtsBackend::resume_from(const std::string& restart, double time) {
  if (lmp_) throw std::logic_error("LiggghtsBackend::resume_from after initialize");
  resume_restart_ = restart;
  resume_time_ = time;
}

void LiggghtsBackend::write_restart(const std::string& file) {
  // Not LIGGGHTS's write_restart command: it re-initialises the run and exchanges the atoms
  // first, so the next substeps would have to set the run up again, and that alone (neighbour
  // lists rebuilt in another order) sends the grains' contacts down another round-off path than
  // the same run without a checkpoint (1e-6 v_in between 1 and 2 ranks of the erosion layer).
  // The file alone is written: the contact histories copied from the neighbour lists into the
  // atoms' arrays (the command's pre_exchange; harmless mid-run, the next reneighbouring does it
  // again), then WriteRestart::write, periodic coordinates remapped into the box in its buffer.
  if (file.find('%') != std::string::npos)
    throw std::invalid_argument("write_restart: LIGGGHTS would expand '%' in '" + file + "'");
  auto* modify = lmp_->modify;
  for (int i = 0; i < modify->nfix; i++)
    if (std::strcmp(modify->fix[i]->style, "contacthistory") == 0) modify->fix[i]->pre_exchange();
  const int remap = modify->restart_pbc_any;
  modify->restart_pbc_any = 1;
  std::vector<char> name(file.begin(), file.end());
  name.push_back('\0');
  LAMMPS_NS::WriteRestart(lmp_.get()).write(name.data());
  modify->restart_pbc_any = remap;
}

void LiggghtsBackend::finalize() {
  // LIGGGHTS hands a restart's multisphere data to fix multisphere only when a run sets it up,
  // and its Modify destructor stops with an error (Error::all, exit() inside a destructor: a
  // segmentation fault) when it never was: a case refused after the DEM script ran (a fluid step
  // beyond the stability limits, a bad coupling key) crashed on the way out instead of showing
  // its message. A run of no steps sets it up (where there is a box to run in).
  if (lmp_ && !ran_ && lmp_->domain->box_exist) {
    set_liggghts_context(lmp_, "the run of 0 steps isphdem gives before closing LIGGGHTS");
    command("run 0 post no");
  }
  if (lmp_) forget_restart_redirect(lmp_.get());
  lmp_.reset();
}

LAMMPS_NS::FixCoupleIsph* LiggghtsBackend::coupling_fix() {
  LAMMPS_NS::FixCoupleIsph* found = nullptr;
  auto* modify = lmp_->modify;
  for (int i = 0; i < modify->nfix; i++)
    if (auto* f = dynamic_cast<LAMMPS_NS::FixCoupleIsph*>(modify->fix[i])) {
      if (found) throw std::runtime_error("the DEM script defines more than one fix couple/isph");
      found = f;
    }
  if (!found)
    throw std::runtime_error(
        "the DEM script has no `fix ID group couple/isph`: add one to receive fluid loads");
  return found;
}

LAMMPS_NS::FixMultisphere* LiggghtsBackend::multisphere() {
  auto* modify = lmp_->modify;
  for (int i = 0; i < modify->nfix; i++)
    if (auto* f = dynamic_cast<LAMMPS_NS::FixMultisphere*>(modify->fix[i])) return f;
  return nullptr;
}

void LiggghtsBackend::set_atom_loads(const std::vector<int>& tags, const std::vector<Vec3>& force,
                                     const std::vector<Vec3>& torque) {
  auto* fix = coupling_fix();
  FlatLoads l = broadcast_loads(comm_, rank_, tags, force, torque, "set_atom_loads");
  auto* atom = lmp_->atom;
  if (atom->map_style == 0)
    throw std::runtime_error(
        "set_atom_loads: the DEM script needs 'atom_modify map array' (loads are keyed by tag)");
  require_all_owned(
      comm_, l.ids,
      [&](int tag) {
        if (tag < 1 || tag > atom->map_tag_max) return false;
        const int i = atom->map(tag);
        return i >= 0 && i < atom->nlocal && (atom->mask[i] & fix->groupbit);
      },
      "set_atom_loads: no atom in the group of fix couple/isph has tag");
  fix->set_atom_loads(static_cast<int>(l.ids.size()), l.ids.data(), l.force.data(),
                      l.torque.data());
}

void LiggghtsBackend::set_body_loads(const std::vector<int>& ids, const std::vector<Vec3>& force,
                                     const std::vector<Vec3>& torque) {
  auto* fix = coupling_fix();
  FlatLoads l = broadcast_loads(comm_, rank_, ids, force, torque, "set_body_loads");
  auto* ms = multisphere();
  if (!ms && !l.ids.empty())
    throw std::invalid_argument("set_body_loads: the DEM script has no fix multisphere");
  require_all_owned(
      comm_, l.ids,
      [&](int id) {
        auto& data = ms->data();
        return id >= 0 && id <= data.tag_max_body() && data.map(id) >= 0;
      },
      "set_body_loads: no multisphere body has id");
  fix->set_body_loads(static_cast<int>(l.ids.size()), l.ids.data(), l.force.data(),
                      l.torque.data());
}

const DemState& LiggghtsBackend::state() {
  if (state_stale_) gather_state();
  return state_;
}

void LiggghtsBackend::gather_state() {
  auto* atom = lmp_->atom;
  auto* ms = multisphere();

  constexpr int kAtomRow = 12;  // tag, x3, v3, omega3, radius, body
  std::vector<double> rows;
  rows.reserve(static_cast<size_t>(atom->nlocal) * kAtomRow);
  for (int i = 0; i < atom->nlocal; i++) {
    rows.push_back(atom->tag[i]);
    rows.insert(rows.end(), atom->x[i], atom->x[i] + 3);
    rows.insert(rows.end(), atom->v[i], atom->v[i] + 3);
    rows.insert(rows.end(), atom->omega[i], atom->omega[i] + 3);
    rows.push_back(atom->radius[i]);
    rows.push_back(ms ? ms->belongs_to(i) : -1);
  }
  std::vector<double> all = allgather(comm_, rows);
  state_.atoms.resize(all.size() / kAtomRow);
  for (size_t a = 0; a < state_.atoms.size(); a++) {
    const double* r = &all[a * kAtomRow];
    DemAtom& d = state_.atoms[a];
    d.tag = static_cast<int>(r[0]);
    std::copy(r + 1, r + 4, d.x.begin());
    std::copy(r + 4, r + 7, d.v.begin());
    std::copy(r + 7, r + 10, d.omega.begin());
    d.radius = r[10];
    d.body = static_cast<int>(r[11]);
  }
  std::sort(state_.atoms.begin(), state_.atoms.end(),
            [](const DemAtom& a, const DemAtom& b) { return a.tag < b.tag; });

  state_.bodies.clear();
  if (ms) {
    constexpr int kBodyRow = 28;  // id, x3, v3, omega3, quat4, mass, volume, inertia3, axes9
    LAMMPS_NS::Multisphere& data = ms->data();
    double** inertia = data.extract_double_vector("inertia");
    double** axes[3] = {data.extract_double_vector("ex_space"),
                        data.extract_double_vector("ey_space"),
                        data.extract_double_vector("ez_space")};
    rows.clear();
    for (int b = 0; b < data.n_body(); b++) {
      double v[4];
      rows.push_back(data.tag(b));
      data.xcm(v, b);
      rows.insert(rows.end(), v, v + 3);
      data.vcm(v, b);
      rows.insert(rows.end(), v, v + 3);
      data.omega(v, b);
      rows.insert(rows.end(), v, v + 3);
      data.quat(v, b);
      rows.insert(rows.end(), v, v + 4);
      rows.push_back(data.mass(b));
      rows.push_back(data.volume(b));
      rows.insert(rows.end(), inertia[b], inertia[b] + 3);
      for (auto& e : axes) rows.insert(rows.end(), e[b], e[b] + 3);
    }
    all = allgather(comm_, rows);
    state_.bodies.resize(all.size() / kBodyRow);
    for (size_t k = 0; k < state_.bodies.size(); k++) {
      const double* r = &all[k * kBodyRow];
      DemBody& d = state_.bodies[k];
      d.id = static_cast<int>(r[0]);
      std::copy(r + 1, r + 4, d.x.begin());
      std::copy(r + 4, r + 7, d.v.begin());
      std::copy(r + 7, r + 10, d.omega.begin());
      std::copy(r + 10, r + 14, d.quat.begin());
      d.mass = r[14];
      d.volume = r[15];
      std::copy(r + 16, r + 19, d.inertia.begin());
      for (int e = 0; e < 3; e++) std::copy(r + 19 + 3 * e, r + 22 + 3 * e, d.axes[e].begin());
      d.members.clear();
    }
    std::sort(state_.bodies.begin(), state_.bodies.end(),
              [](const DemBody& a, const DemBody& b) { return a.id < b.id; });
    std::map<int, size_t> by_id;
    for (size_t k = 0; k < state_.bodies.size(); k++) by_id[state_.bodies[k].id] = k;
    for (const auto& a : state_.atoms)
      if (a.body >= 0 && by_id.count(a.body)) state_.bodies[by_id[a.body]].members.push_back(a.tag);
  }
  state_.step = lmp_->update->ntimestep;
  state_stale_ = false;
}

}  // namespace isphdem
