// PLACEHOLDER for the dem branch only: lets `isphdem` link here. Drop at merge.
#include <cstdio>

#include "run_command.hpp"

namespace isphdem {
int run_main(int, char**) {
  std::fprintf(stderr, "isphdem run: not in this branch\n");
  return 2;
}
}  // namespace isphdem
