#include "dem/liggghts_output_tee.hpp"

#include <unistd.h>

#include <cstring>
#include <string_view>

#include "dem/liggghts_error_hints.hpp"
#include "input.h"
#include "lammps.h"
#include "universe.h"

namespace isphdem {

namespace {

// Input::command (the command being executed) is protected; a derived class may form a pointer
// to it. The class is never instantiated.
struct InputCommand : LAMMPS_NS::Input {
  static char* LAMMPS_NS::Input::*member() { return &InputCommand::command; }
};

bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }
bool ends_with(std::string_view s, std::string_view p) {
  return s.size() >= p.size() && s.substr(s.size() - p.size()) == p;
}

// LIGGGHTS writes an error as "ERROR: msg (file:line)\n" or "ERROR on proc N: msg (file:line)\n";
// the log copy of the stray write that may follow has a leading space.
bool is_error(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  return starts_with(s, "ERROR");
}

std::string error_suffix(std::string_view s) {
  const auto at = s.rfind(" (");
  return at == std::string_view::npos || !ends_with(s, ")\n") ? "" : std::string(s.substr(at));
}

}  // namespace

LiggghtsOutputTee::LiggghtsOutputTee(LAMMPS_NS::LAMMPS* lmp, int rank)
    : lmp_(lmp), rank_(rank), host_stdout_(stdout) {
  install(screen_, lmp_->screen, lmp_->universe->uscreen, true);
  install(log_, lmp_->logfile, lmp_->universe->ulogfile, false);
}

void LiggghtsOutputTee::install(Stream& s, FILE*& member, FILE*& universe_member, bool is_screen) {
  s.owner = this;
  s.real = member;
  s.is_screen = is_screen;
  // The log has nothing to pass on where LIGGGHTS opened none (ranks > 0, -log none); the screen
  // still carries the ERROR lines of Error::one there.
  if (!s.real && !is_screen) return;
  cookie_io_functions_t io{};
  io.write = &LiggghtsOutputTee::write;
  io.close = &LiggghtsOutputTee::close;
  s.ours = fopencookie(&s, "w", io);
  if (!s.ours) return;  // keep LIGGGHTS's own stream
  // Unbuffered: each fprintf of LIGGGHTS is one write here, and nothing waits in a buffer when
  // Error::one calls MPI_Abort.
  std::setvbuf(s.ours, nullptr, _IONBF, 0);
  member = s.ours;
  // With one partition the universe's stream is the same file: route it through us too.
  if (universe_member == s.real && s.real) universe_member = s.ours;
}

void LiggghtsOutputTee::close() {
  host_closing_ = true;
  for (Stream* s : {&screen_, &log_})
    if (s->ours && !s->closed) std::fclose(s->ours);
}

FILE* LiggghtsOutputTee::capture_stdout() {
  FILE* previous = stdout;
  if (!screen_.ours || screen_.closed) return previous;
  std::fflush(stdout);  // isphdem's own lines first
  stdout = screen_.ours;
  return previous;
}

void LiggghtsOutputTee::release_stdout(FILE* previous) {
  // A capture nested in one whose screen has closed since gives back isphdem's stdout.
  stdout = previous == screen_.ours && screen_.closed ? host_stdout_ : previous;
}

ssize_t LiggghtsOutputTee::write(void* cookie, const char* buf, size_t size) {
  auto& s = *static_cast<Stream*>(cookie);
  const std::string_view text(buf, size);
  const bool error = is_error(text);
  if (!s.error_suffix.empty()) {
    const bool stray = !error && ends_with(text, s.error_suffix);
    s.error_suffix.clear();
    if (stray) return static_cast<ssize_t>(size);
  }
  if (error) {
    s.error_suffix = error_suffix(text);
    if (s.is_screen) s.owner->report_error(std::string(text));
  }
  // Flushed every write: another rank's MPI_Abort may end this process at any moment, and a
  // coupled run writes a few lines per fluid step, so the cost is small.
  if (s.real && (std::fwrite(buf, 1, size, s.real) != size || std::fflush(s.real) != 0)) return -1;
  return static_cast<ssize_t>(size);
}

int LiggghtsOutputTee::close(void* cookie) {
  auto& s = *static_cast<Stream*>(cookie);
  s.closed = true;
  if (stdout == s.ours) stdout = s.owner->host_stdout_;  // never a closed stream
  if (s.real) {
    if (s.real == stdout)
      std::fflush(s.real);
    else
      std::fclose(s.real);
  }
  const LiggghtsOutputTee& tee = *s.owner;
  if (!tee.host_closing_ && s.is_screen && tee.rank_ == 0)
    std::fprintf(stderr,
                 "isphdem: LIGGGHTS ends the process after this error (exit status 1); output "
                 "written before it is complete\n");
  return 0;
}

std::string LiggghtsOutputTee::running_command() const {
  const char* command = lmp_->input ? lmp_->input->*InputCommand::member() : nullptr;
  if (!command || !*command) return "";
  std::string line = command;
  for (int i = 0; i < lmp_->input->narg; ++i) line += std::string(" ") + lmp_->input->arg[i];
  return line;
}

void LiggghtsOutputTee::report_error(const std::string& line) const {
  std::string msg = isatty(STDERR_FILENO) ? "\n" : "";  // past a progress line
  msg += "isphdem: LIGGGHTS stopped the run:\n  " + line;
  const std::string command = running_command();
  if (!command.empty()) msg += "  while running `" + command + "`";
  if (!context_.empty()) msg += (command.empty() ? "  in " : " in ") + context_;
  if (!command.empty() || !context_.empty()) msg += "\n";
  const std::string hint = liggghts_error_hint(line);
  if (!hint.empty()) msg += "  hint: " + hint + "\n";
  std::fputs(msg.c_str(), stderr);
  std::fflush(stderr);
}

}  // namespace isphdem
