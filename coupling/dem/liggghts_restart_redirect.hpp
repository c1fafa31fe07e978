// Resuming a coupled run from its checkpoint (docs/output.md, "Checkpoints and --resume"): the
// case's DEM script builds its grains from `read_restart FILE` (examples/internal_erosion_2d
// reads its packing so), and a resumed run must read the checkpoint's LIGGGHTS restart there
// instead, then run the rest of the script as the first run did (contacts, fixes; `fix
// multisphere` takes its bodies from the restart). LIGGGHTS 3.8 offers no hook for that: its
// command table `Input::command_map` is protected, and is reached as liggghts_fix/ reaches
// Modify::fix_map (the explicit-instantiation access idiom).
#ifndef ISPHDEM_LIGGGHTS_RESTART_REDIRECT_HPP
#define ISPHDEM_LIGGGHTS_RESTART_REDIRECT_HPP

#include <string>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace isphdem {

// From now on every `read_restart FILE ...` of this LIGGGHTS instance reads `file` instead of
// FILE (the other arguments kept).
void redirect_read_restart(LAMMPS_NS::LAMMPS* lmp, const std::string& file);
// How many read_restart commands were redirected so far.
int redirected_restarts(LAMMPS_NS::LAMMPS* lmp);
// Forgets the instance (before it is deleted).
void forget_restart_redirect(LAMMPS_NS::LAMMPS* lmp);

}  // namespace isphdem

#endif
