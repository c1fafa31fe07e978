#include "dem/dem_liggghts_session.hpp"

#include "lammps.h"
#include "register_couple_isph.h"

namespace isphdem {

void LammpsCloser::operator()(LAMMPS_NS::LAMMPS* lmp) const { delete lmp; }

LammpsHandle open_liggghts(const std::vector<std::string>& args, MPI_Comm comm) {
  std::vector<std::string> storage;
  storage.reserve(args.size() + 1);
  storage.push_back("isphdem");
  storage.insert(storage.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& s : storage) argv.push_back(s.data());
  argv.push_back(nullptr);
  LammpsHandle lmp(new LAMMPS_NS::LAMMPS(static_cast<int>(storage.size()), argv.data(), comm));
  register_couple_isph(lmp.get());
  return lmp;
}

}  // namespace isphdem
