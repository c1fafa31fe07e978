#pragma once
// The fluid decomposed over processes (issue 26): each process holds the particles it owns and,
// during a step, a halo behind them, copies of other processes' particles within a kernel support
// of its region, so that every kernel sum over an owned particle is complete. The stages of a
// step then run over the owned rows [first, last) = [0, owned) as they do over a block of shared
// rows (sph/row_share.hpp), and exchange() refreshes the halo from the owners. The MPI
// implementation is sph_mpi/rcb_decomposition.hpp; sph/ itself never sees MPI.
#include <cstdint>
#include <memory>
#include <vector>

#include "linear_solver.hpp"
#include "particles.hpp"
#include "row_share.hpp"

namespace isph {

template <int Dim>
class Decomposition : public RowShare {
 public:
  bool decomposed() const override { return true; }
  // Between steps (no halo): sends the owned particles that left this process's region to their
  // owners, first re-cutting the regions when the load has drifted. `carried` (optional, the same
  // choice on every process): one more value per particle, aligned with p, that travels with its
  // particle. Returns how many particles changed process, over all processes (the same on every
  // process).
  virtual int64_t migrate(Particles<Dim>& p, std::vector<double>* carried) = 0;
  // Appends the halo: copies of the particles of other processes within `width` of this one's
  // region, with all their arrays. Rows [0, owned) stay this process's.
  virtual void add_halo(Particles<Dim>& p, double width) = 0;
  virtual void drop_halo(Particles<Dim>& p) = 0;
  // The pressure equation's numbering of the present owned and halo rows (since add_halo).
  virtual std::shared_ptr<const GlobalNumbering> numbering() const = 0;
};

}  // namespace isph
