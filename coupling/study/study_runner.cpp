#include "study/study_runner.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <toml++/toml.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <stdexcept>
#include <thread>

#include "io/checkpoint.hpp"
#include "io/progress_line.hpp"
#include "study/diagnostics_table.hpp"

namespace isphdem {

namespace fs = std::filesystem;

namespace {

double now_seconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

std::string last_line(const fs::path& log) {
  std::ifstream in(log);
  std::string line, last;
  while (std::getline(in, line))
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  return last;
}

// Starts `isphdem run` for one point with its output going to DIR/log.txt. The child dies with
// the study (PR_SET_PDEATHSIG), so a killed study leaves no orphan writing into its directories.
pid_t start_point(const Study& study, const StudyPoint& p, const fs::path& dir,
                  const StudyRunOptions& o, const std::string& threads, bool resume) {
  std::vector<std::string> args{o.isphdem.string(), "run", study.base.string(), "--out",
                                dir.string()};
  for (const auto& s : p.overrides) {
    args.push_back("--set");
    args.push_back(s);
  }
  if (resume) args.push_back("--resume");
  const std::string log = (dir / "log.txt").string();
  std::vector<char*> argv;  // built before fork: the child only calls async-signal-safe functions
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string omp = "OMP_NUM_THREADS=" + threads;
  std::vector<char*> env;
  for (char** e = environ; *e; ++e)
    if (threads.empty() || std::strncmp(*e, "OMP_NUM_THREADS=", 16) != 0) env.push_back(*e);
  if (!threads.empty()) env.push_back(const_cast<char*>(omp.c_str()));
  env.push_back(nullptr);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("cannot start a process for point '" + p.name + "'");
  if (pid > 0) return pid;
  prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (getppid() != parent) _exit(127);  // the study died before prctl took hold
  const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) _exit(126);
  dup2(fd, STDOUT_FILENO);
  dup2(fd, STDERR_FILENO);
  close(fd);
  execve(argv[0], argv.data(), env.data());
  static const char kFailed[] = "isphdem study: cannot start isphdem run\n";
  [[maybe_unused]] const auto written = write(STDERR_FILENO, kFailed, sizeof kFailed - 1);
  _exit(127);
}

PointOutcome outcome_of(const fs::path& dir, int wait_status) {
  PointOutcome out;
  const auto r = read_run_result(dir / run_result_file_name());
  if (r) {
    out.result = *r;
    out.status = r->status;
    out.message = r->message;
    return out;
  }
  if (WIFSIGNALED(wait_status)) {
    out.status = "killed";
    out.message = std::string("signal ") + std::to_string(WTERMSIG(wait_status)) + " (" +
                  strsignal(WTERMSIG(wait_status)) + ")";
  } else {
    out.status = "failed";
    out.message = "exit status " + std::to_string(WEXITSTATUS(wait_status)) + ": " +
                  last_line(dir / "log.txt");
  }
  return out;
}

std::string describe(const PointOutcome& o) {
  std::string s = o.status;
  if (o.status == "finished" || o.status == "stopped") {
    char buf[64];
    std::snprintf(buf, sizeof buf, " in %s", format_duration(o.result.wall_seconds).c_str());
    s += buf;
    for (const auto& m : o.result.metrics) {
      // A metric with no expected value (a study's reference point gives it one at the end).
      if (std::isnan(m.error))
        std::snprintf(buf, sizeof buf, ", %s %.4g", m.name.c_str(), m.value);
      else
        std::snprintf(buf, sizeof buf, ", %s %s%.3g%s", m.name.c_str(), m.error >= 0 ? "+" : "",
                      m.relative ? 100 * m.error : m.error, m.relative ? "%" : "");
      s += buf;
    }
  }
  if (!o.message.empty()) s += ": " + o.message;
  return s;
}

// How much longer a running point needs, from how far its diagnostics.csv has come against the
// time.end of its case_used.toml; NaN while it has written no row yet (or is not a timed run).
double remaining_seconds(const fs::path& dir) {
  try {
    const auto t = read_diagnostics(dir / "diagnostics.csv");
    const toml::table used = toml::parse_file((dir / "case_used.toml").string());
    const double t_end = used["time"]["end"].value<double>().value_or(NAN);
    if (t.rows() == 0 || !t.has("time") || !t.has("wall_seconds")) return NAN;
    const double now = t.columns.at("time").back(), wall = t.columns.at("wall_seconds").back();
    if (!(now > 0.0) || !(wall > 0.0) || std::isnan(t_end)) return NAN;
    if (now >= t_end) return 0.0;
    return wall * (t_end - now) / now;
  } catch (const std::exception&) {
    return NAN;
  }
}

// The rest of the study: the running points from their own progress (or, before their first
// row, the mean point), the queued ones at the mean point, over the jobs; never less than the
// longest running point still needs. Points of one study can differ in cost a hundredfold, so
// the mean alone said seconds where a fine point had minutes to go.
double eta_seconds(const std::vector<std::pair<fs::path, double>>& running, std::size_t queued,
                   double mean_point, int jobs) {
  double work = mean_point * double(queued), longest = 0.0;
  for (const auto& [dir, started] : running) {
    double rest = remaining_seconds(dir);
    if (std::isnan(rest)) rest = std::max(0.0, mean_point - (now_seconds() - started));
    work += rest;
    longest = std::max(longest, rest);
  }
  return std::max(longest, work / double(std::max(1, jobs)));
}

}  // namespace

std::vector<PointOutcome> run_study(const Study& study, const StudyRunOptions& o) {
  const std::size_t n = study.points.size();
  std::vector<PointOutcome> outcomes(n);
  std::vector<std::size_t> pending;
  std::size_t done = 0;
  auto say = [&](std::size_t k, const std::string& what) {
    if (o.quiet) return;
    std::printf("study: [%zu/%zu] %s: %s\n", done, n, study.points[k].name.c_str(), what.c_str());
    std::fflush(stdout);
  };
  // A point is the same as before when its case file, that file's text and its overrides are.
  const std::string fingerprint = case_fingerprint(study.base);
  for (std::size_t k = 0; k < n; ++k) {
    const fs::path dir = o.out / study.points[k].name;
    const auto earlier = read_run_result(dir / run_result_file_name());
    if (earlier && (earlier->status == "finished" || earlier->status == "stopped") &&
        earlier->overrides == study.points[k].overrides &&
        earlier->case_file == study.base.string() && earlier->case_fingerprint == fingerprint) {
      outcomes[k] = {earlier->status, earlier->message, true, *earlier};
      ++done;
      say(k, "done earlier (" + describe(outcomes[k]) + "), not run again");
    } else {
      pending.push_back(k);
    }
  }
  // Each point gets an equal share of the cores unless the user chose OMP_NUM_THREADS.
  std::string threads;
  if (!std::getenv("OMP_NUM_THREADS")) {
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    threads = std::to_string(std::max(1u, cores / unsigned(std::max(1, o.jobs))));
  }
  std::map<pid_t, std::pair<std::size_t, double>> running;  // pid -> point, start time
  double run_wall = 0.0;
  std::size_t run_count = 0, next = 0;
  while (next < pending.size() || !running.empty()) {
    while (next < pending.size() && running.size() < std::size_t(std::max(1, o.jobs))) {
      const std::size_t k = pending[next++];
      const fs::path dir = o.out / study.points[k].name;
      fs::create_directories(dir);
      // A point stopped (interrupted, killed) after a checkpoint of this very point goes on from
      // it; an earlier point's checkpoint (another case text or --set) is not taken.
      const auto identity = checkpoint_identity(dir);
      const bool resume =
          identity && *identity == run_identity(fingerprint, study.points[k].overrides);
      remove_run_result(dir);
      // The ETA reads these while the point runs: an earlier run's must not stand for it (a
      // resumed point's diagnostics.csv is its own, continued).
      fs::remove(dir / "case_used.toml");
      if (!resume) fs::remove(dir / "diagnostics.csv");
      if (resume) say(k, "resumes from its checkpoint");
      running[start_point(study, study.points[k], dir, o, threads, resume)] = {k, now_seconds()};
    }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error("lost track of the point processes (waitpid failed)");
    }
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    const auto [k, started] = it->second;
    running.erase(it);
    outcomes[k] = outcome_of(o.out / study.points[k].name, status);
    run_wall += now_seconds() - started;
    ++run_count;
    ++done;
    std::string eta;
    const std::size_t left = pending.size() - next + running.size();
    if (left > 0) {
      std::vector<std::pair<fs::path, double>> busy;
      for (const auto& [p, point] : running)
        busy.emplace_back(o.out / study.points[point.first].name, point.second);
      eta = " (" + std::to_string(running.size()) + " running, ETA " +
            format_duration(
                eta_seconds(busy, pending.size() - next, run_wall / double(run_count), o.jobs)) +
            ")";
    }
    say(k, describe(outcomes[k]) + eta);
  }
  return outcomes;
}

}  // namespace isphdem
