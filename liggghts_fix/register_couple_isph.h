// Run-time registration of `fix couple/isph` into Debian's prebuilt libliggghts, whose style
// table is compiled in (DESIGN.md decision 1). Call register_couple_isph right after
// constructing LAMMPS, before any input is read.
#ifndef ISPHDEM_REGISTER_COUPLE_ISPH_H
#define ISPHDEM_REGISTER_COUPLE_ISPH_H

namespace LAMMPS_NS {
class LAMMPS;
}

namespace isphdem {

// Adds `couple/isph` to lmp's fix styles (idempotent).
void register_couple_isph(LAMMPS_NS::LAMMPS* lmp);

// Whether `fix ... STYLE` would be accepted by lmp (looks up the same table).
bool fix_style_registered(LAMMPS_NS::LAMMPS* lmp, const char* style);

}  // namespace isphdem

#endif
