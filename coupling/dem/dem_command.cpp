#include "dem/dem_command.hpp"

#include <mpi.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "dem/dem_liggghts_session.hpp"
#include "input.h"
#include "lammps.h"

namespace isphdem {

namespace {

constexpr const char* kUsage =
    "usage: isphdem dem SCRIPT [-var NAME VALUE ...] [-log FILE|none] [-screen FILE|none] "
    "[-echo none|screen|log|both] [other liggghts options]\n"
    "Runs a LIGGGHTS input script like `liggghts -in SCRIPT`, with `fix couple/isph` "
    "available.\n";

}  // namespace

int dem_main(int argc, char** argv) {
  if (argc < 2) {
    std::fputs(kUsage, stderr);
    return 2;
  }
  const std::string script = argv[1];
  if (script == "-h" || script == "--help") {
    std::fputs(kUsage, stdout);
    return 0;
  }
  std::vector<std::string> args = {"-in", script};
  for (int i = 2; i < argc; i++) {
    if (!std::strcmp(argv[i], "-in") || !std::strcmp(argv[i], "-i"))
      throw std::runtime_error("the input script is the first argument of `isphdem dem`; drop -in");
    args.push_back(argv[i]);
  }
  // Checked here because LIGGGHTS would only say "Cannot open input script" after starting up.
  if (std::filesystem::is_directory(script) || !std::ifstream(script))
    throw std::runtime_error("cannot open input script '" + script + "': no such readable file");

  auto lmp = open_liggghts(args, MPI_COMM_WORLD);
  set_liggghts_context(lmp, "script " + script);
  const LiggghtsStdoutToScreen to_screen(lmp);
  lmp->input->file();  // reads the -in script, as the stock launcher does
  return 0;
}

}  // namespace isphdem
