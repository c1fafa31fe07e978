#include "run/ranks_notice.hpp"

#include <cstdio>

namespace isphdem {

RanksNotice ranks_notice(int ranks, bool decomposed, const std::string& preconditioner) {
  RanksNotice n;
  if (ranks <= 1) return n;
  const std::string count = "ranks: " + std::to_string(ranks) + ", ";
  if (decomposed) {
    n.header = count + "fluid decomposed (each rank steps its own region)";
  } else if (preconditioner == "amg") {
    n.header = count +
               "fluid held by every rank, each computing its block of rows "
               "(parallel.decompose = false)";
  } else {
    n.header = count + "fluid replicated (every rank steps all of it)";
    n.warning = "solver.preconditioner = \"" + preconditioner +
                "\" does not decompose: each of the " + std::to_string(ranks) +
                " ranks steps the whole fluid, so the fluid runs no faster than on one; set "
                "--set solver.preconditioner=amg (solver.preconditioner = \"amg\" in the case) "
                "to share it over the ranks";
  }
  return n;
}

void say_ranks(const RanksNotice& n, int rank, bool talk) {
  if (talk && !n.header.empty()) std::printf("  %s\n", n.header.c_str());
  if (talk) std::fflush(stdout);
  if (rank == 0 && !n.warning.empty()) {
    std::fprintf(stderr, "isphdem run: warning: %s\n", n.warning.c_str());
    std::fflush(stderr);
  }
}

}  // namespace isphdem
