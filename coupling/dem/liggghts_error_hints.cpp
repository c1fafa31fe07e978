#include "dem/liggghts_error_hints.hpp"

#include <utility>

namespace isphdem {

namespace {

// (text in LIGGGHTS 3.8's message, hint). The first match wins, so specific entries come first.
const std::pair<const char*, const char*> kHints[] = {
    {"illegal number of spheres",
     "a single sphere is not a multisphere body; use a plain sphere (fix particletemplate/sphere) "
     "or give particletemplate/multisphere nspheres >= 2"},
    {"Incorrect args for pair coefficients",
     "granular pair styles take no coefficients: write `pair_coeff * *` and give the material "
     "(kn, kt, gamman, youngsModulus, ...) with `fix property/global`"},
    {"Invalid fix style",
     "check the spelling of the fix style; Debian's LIGGGHTS 3.8 knows the styles `liggghts -h` "
     "lists, and isphdem adds couple/isph"},
    {"Invalid pair style",
     "check the spelling of the pair style (granular: `pair_style gran model ...`)"},
    {"Unknown command", "check the spelling of the command, or whether it exists in LIGGGHTS 3.8"},
    {"Insertion region extends outside simulation box",
     "shrink the insertion region to lie inside the region given to create_box"},
    {"Set command with no atoms existing",
     "no grain was created: a create_atoms point outside the simulation box creates nothing, so "
     "move it inside the region given to create_box"},
    {"Lost atoms",
     "a grain left the DEM box through a fixed (f) boundary: enlarge the box or close it with "
     "walls; in a coupled run, also check the fluid time step (a too-large drag flings grains)"},
    {"Cannot open input script", "check the script path (relative paths start at the case file)"},
};

}  // namespace

std::string liggghts_error_hint(const std::string& error_line) {
  for (const auto& [text, hint] : kHints)
    if (error_line.find(text) != std::string::npos) return hint;
  return "";
}

}  // namespace isphdem
