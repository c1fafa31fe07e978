#include "dem/liggghts_restart_redirect.hpp"

#include <map>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "input.h"
#include "lammps.h"

namespace {

// Same as the protected typedef Input::CommandCreator.
using CommandCreator = void (*)(LAMMPS_NS::LAMMPS*, int, char**);
using CommandMap = std::map<std::string, CommandCreator>;

struct InputCommandMap {
  using type = CommandMap* LAMMPS_NS::Input::*;
  friend type member(InputCommandMap);  // defined by the instantiation below
};

template <typename Tag, typename Tag::type Member>
struct Expose {
  friend typename Tag::type member(Tag) { return Member; }
};

template struct Expose<InputCommandMap, &LAMMPS_NS::Input::command_map>;

CommandMap& command_map(LAMMPS_NS::LAMMPS* lmp) {
  return *(lmp->input->*member(InputCommandMap{}));
}

struct Redirect {
  std::string file;
  CommandCreator original = nullptr;
  int count = 0;
};

std::mutex redirects_mutex;
std::map<LAMMPS_NS::LAMMPS*, Redirect>& redirects() {
  static std::map<LAMMPS_NS::LAMMPS*, Redirect> r;
  return r;
}

void redirected_read_restart(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) {
  Redirect r;
  {
    std::lock_guard<std::mutex> lock(redirects_mutex);
    auto& entry = redirects().at(lmp);
    ++entry.count;
    r = entry;
  }
  std::vector<char> file(r.file.begin(), r.file.end());
  file.push_back('\0');
  std::vector<char*> args(arg, arg + narg);
  if (!args.empty()) args[0] = file.data();
  r.original(lmp, narg, args.data());
}

}  // namespace

namespace isphdem {

void redirect_read_restart(LAMMPS_NS::LAMMPS* lmp, const std::string& file) {
  CommandMap& map = command_map(lmp);
  const auto it = map.find("read_restart");
  if (it == map.end()) throw std::logic_error("LIGGGHTS has no read_restart command to redirect");
  std::lock_guard<std::mutex> lock(redirects_mutex);
  Redirect& r = redirects()[lmp];
  if (it->second != &redirected_read_restart) r.original = it->second;
  r.file = file;
  it->second = &redirected_read_restart;
}

int redirected_restarts(LAMMPS_NS::LAMMPS* lmp) {
  std::lock_guard<std::mutex> lock(redirects_mutex);
  const auto it = redirects().find(lmp);
  return it == redirects().end() ? 0 : it->second.count;
}

void forget_restart_redirect(LAMMPS_NS::LAMMPS* lmp) {
  std::lock_guard<std::mutex> lock(redirects_mutex);
  redirects().erase(lmp);
}

}  // namespace isphdem
