#pragma once
// `isphdem run` on several MPI ranks, as it is today: every rank holds the whole fluid and steps
// it alike, each computing its block of rows (sph/row_share.hpp; the pressure equation is one
// system over the ranks, sph_petsc/). The ranks write each snapshot together, each its block of
// rows (io/snapshot_writer.hpp); rank 0 writes diagnostics.csv. Two things follow: the copies
// must stay identical, or each rank would enter its rows of the pressure system from a different
// flow (checked at every snapshot: a cheap sum of positions, velocities and pressures compared
// bit for bit); and a failure of the output must stop every rank, not leave the others waiting
// in the next pressure solve.
#include <functional>

#include "particles.hpp"

namespace isphdem {

// isph::SimulationError (cause "replicas") naming the step when the ranks' copies differ; does
// nothing on one rank. Collective: every rank must call it.
template <int Dim>
void check_replicas(const isph::Particles<Dim>& particles, long step);

// Runs `write` on rank 0 only. If it throws while other ranks run, the message is printed and
// MPI_Abort stops every rank (the snapshots written before stay complete); on one rank the
// exception goes on to the caller as usual.
void write_on_rank_zero(int rank, const std::function<void()>& write);

// Runs `make` on every rank. With `collective`, if it throws on some ranks, every rank throws a
// CaseError with the message of the lowest rank that failed: for checks that see only a rank's
// own share of the particles (a split scene, build_fluid_scene), so that no rank goes on alone.
// Without, the exception goes on to the caller as usual.
void agree_on_failure(bool collective, const std::function<void()>& make);

// Runs `write` (a collective snapshot write) on every rank. If it throws on several ranks, rank 0
// prints the message and MPI_Abort stops every rank; on one rank the exception goes on to the
// caller as usual.
void write_collectively(int rank, const std::function<void()>& write);

}  // namespace isphdem
