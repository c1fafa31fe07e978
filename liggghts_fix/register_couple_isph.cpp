// LIGGGHTS 3.8 keeps its fix-style table in the private member `Modify::fix_map` and offers no
// way to add to it at run time. We reach it with the explicit-instantiation access idiom, the
// one standard-conforming way to name a private member from outside: [temp.explicit]/12 lets an
// explicit instantiation name `&Modify::fix_map` despite its access, and the instantiated
// class template hands that pointer-to-member out through a friend function. No layout
// assumptions, no #define private public; the type below must match modify.h exactly, so an
// ABI change there fails to compile here instead of corrupting memory.
#include "register_couple_isph.h"

#include <map>
#include <string>

#include "fix_couple_isph.h"
#include "lammps.h"
#include "modify.h"

namespace {

// Same as the private typedef Modify::FixCreator.
using FixCreator = LAMMPS_NS::Fix* (*)(LAMMPS_NS::LAMMPS*, int, char**);
using FixMap = std::map<std::string, FixCreator>;

struct ModifyFixMap {
  using type = FixMap* LAMMPS_NS::Modify::*;
  friend type member(ModifyFixMap);  // defined by the instantiation below
};

template <typename Tag, typename Tag::type Member>
struct Expose {
  friend typename Tag::type member(Tag) { return Member; }
};

template struct Expose<ModifyFixMap, &LAMMPS_NS::Modify::fix_map>;

FixMap& fix_map(LAMMPS_NS::LAMMPS* lmp) { return *(lmp->modify->*member(ModifyFixMap{})); }

LAMMPS_NS::Fix* create_couple_isph(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) {
  return new LAMMPS_NS::FixCoupleIsph(lmp, narg, arg);
}

}  // namespace

namespace isphdem {

void register_couple_isph(LAMMPS_NS::LAMMPS* lmp) {
  fix_map(lmp)[LAMMPS_NS::FixCoupleIsph::kStyle] = &create_couple_isph;
}

bool fix_style_registered(LAMMPS_NS::LAMMPS* lmp, const char* style) {
  return fix_map(lmp).count(style) > 0;
}

}  // namespace isphdem
