#include "dem/dem_liggghts_session.hpp"

#include "lammps.h"
#include "register_couple_isph.h"

namespace isphdem {

void LammpsCloser::operator()(LAMMPS_NS::LAMMPS* lmp) const {
  if (tee) tee->host_closing();
  delete lmp;
  if (tee) tee->close();
}

LammpsHandle open_liggghts(const std::vector<std::string>& args, MPI_Comm comm) {
  std::vector<std::string> storage;
  storage.reserve(args.size() + 1);
  storage.push_back("isphdem");
  storage.insert(storage.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& s : storage) argv.push_back(s.data());
  argv.push_back(nullptr);
  auto* lmp = new LAMMPS_NS::LAMMPS(static_cast<int>(storage.size()), argv.data(), comm);
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  LammpsHandle handle(lmp, LammpsCloser{std::make_shared<LiggghtsOutputTee>(lmp, rank)});
  register_couple_isph(lmp);
  return handle;
}

void set_liggghts_context(LammpsHandle& lmp, std::string where) {
  if (lmp.get_deleter().tee) lmp.get_deleter().tee->set_context(std::move(where));
}

LiggghtsStdoutToScreen::LiggghtsStdoutToScreen(LammpsHandle& lmp) : tee_(lmp.get_deleter().tee) {
  previous_ = tee_ ? tee_->capture_stdout() : stdout;
}

LiggghtsStdoutToScreen::~LiggghtsStdoutToScreen() {
  if (tee_) tee_->release_stdout(previous_);
}

}  // namespace isphdem
