#pragma once
// What a run under mpirun says at its start about its ranks: a line of the run's header (how many
// ranks, and how they share the fluid), and, when the fluid gains nothing from them (a pressure
// preconditioner that does not decompose: every rank steps the whole fluid), a warning naming
// the setting that shares it (docs/parallel.md).
#include <string>

namespace isphdem {

struct RanksNotice {
  std::string header;   // "ranks: 2, ..." without indent; empty on one rank
  std::string warning;  // empty unless the fluid is replicated over several ranks
};

// decomposed: whether the fluid is decomposed over the ranks (what FluidRun::decompose returned);
// preconditioner: solver.preconditioner; "amg" shares the rows of a fluid held by every rank.
RanksNotice ranks_notice(int ranks, bool decomposed, const std::string& preconditioner);

// The header's line on the ranks (when it talks) and the warning of a replicated fluid (rank 0,
// on stderr, even with --quiet); flushes the header.
void say_ranks(const RanksNotice& n, int rank, bool talk);

}  // namespace isphdem
