#include "run/interrupt.hpp"

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <system_error>

namespace isphdem {

namespace {

volatile std::sig_atomic_t received = 0;
struct sigaction previous_int, previous_term;

extern "C" void note_signal(int signal) {
  if (received == signal) {  // the second one: stop now, the default way
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  received = signal;
}

std::string quoted(const std::string& word) {
  if (!word.empty() &&
      word.find_first_not_of(
          "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_./=:+-,@%") ==
          std::string::npos)
    return word;
  std::string q = "'";
  for (char c : word) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

InterruptHandlers::InterruptHandlers() {
  received = 0;
  struct sigaction action {};
  action.sa_handler = note_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // a write under way goes on
  // A signal the run was started ignoring (SIGINT for a background job of a script, nohup) stays
  // ignored.
  sigaction(SIGINT, nullptr, &previous_int);
  sigaction(SIGTERM, nullptr, &previous_term);
  if (previous_int.sa_handler != SIG_IGN) sigaction(SIGINT, &action, nullptr);
  if (previous_term.sa_handler != SIG_IGN) sigaction(SIGTERM, &action, nullptr);
}

InterruptHandlers::~InterruptHandlers() {
  sigaction(SIGINT, &previous_int, nullptr);
  sigaction(SIGTERM, &previous_term, nullptr);
}

int pending_signal() { return received; }

int agreed_signal(MPI_Comm comm) {
  int mine = received, any = mine;
  if (comm != MPI_COMM_NULL) MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, comm);
  return any;
}

std::string resume_command(const std::string& executable, const std::string& case_file,
                           const std::string& out, const std::vector<std::string>& overrides,
                           int ranks) {
  std::string c = ranks > 1 ? "mpirun -np " + std::to_string(ranks) + " " : "";
  c += quoted(executable) + " run " + quoted(case_file) + " --out " + quoted(out);
  for (const auto& o : overrides) c += " --set " + quoted(o);
  return c + " --resume";
}

std::string announce_interruption(const Interrupted& e, const std::string& case_file,
                                  const std::string& out, const std::vector<std::string>& overrides,
                                  int ranks, bool talk) {
  const std::string command =
      resume_command(this_executable("isphdem"), case_file, out, overrides, ranks);
  if (talk) {
    std::fprintf(stderr, "isphdem run: interrupted by %s\n  resume with:\n    %s\n", e.what(),
                 command.c_str());
    std::fflush(stderr);
  }
  return std::string(e.what()) + "; resume with: " + command;
}

std::string this_executable(const std::string& fallback) {
  std::error_code ec;
  const auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? fallback : p.string();
}

}  // namespace isphdem
