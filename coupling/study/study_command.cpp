#include "study/study_command.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <stdexcept>

#include "case/case_file.hpp"
#include "case/verb_arguments.hpp"
#include "io/progress_line.hpp"
#include "study/study_file.hpp"
#include "study/study_runner.hpp"
#include "study/study_table.hpp"

namespace isphdem {

namespace fs = std::filesystem;

namespace {

const char* kUsage =
    "usage: isphdem study STUDY.toml --out DIR [-j N] [--set key=value ...] [--quiet]\n"
    "  --out DIR        one directory per point (DIR/<point>/: log.txt, result.json, the run's\n"
    "                   output), and DIR/study.csv, DIR/study.png; points finished there before\n"
    "                   with the same values are not run again\n"
    "  -j N             run N points side by side (each gets cores / N OpenMP threads unless\n"
    "                   OMP_NUM_THREADS is set)\n"
    "  --set key=value  override a case key in every point (repeatable)\n"
    "  --quiet          no line per point\n";

struct Arguments {
  VerbArguments verb;  // the study file, --out, --set, --quiet
  int jobs = 1;
};

Arguments parse(int argc, char** argv) {
  Arguments a;
  a.verb = parse_verb_arguments(
      argc, argv, "study file", kUsage,
      [&](const std::string& arg, const std::function<std::string()>& value) {
        if (arg.rfind("-j", 0) != 0) return false;
        const std::string n = arg == "-j" ? value() : arg.substr(2);
        char* end = nullptr;
        const long j = std::strtol(n.c_str(), &end, 10);
        if (n.empty() || *end || j < 1 || j > 256)
          throw CaseError("-j '" + n + "': give the number of points to run at once, e.g. -j 2");
        a.jobs = int(j);
        return true;
      });
  return a;
}

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// study.png through scripts/plot_study.py when Debian's python3 with matplotlib is there; the
// CSV is complete either way.
void plot(const Study& study, const fs::path& out, bool quiet, bool has_metrics) {
  const fs::path script = fs::path(ISPHDEM_SCRIPTS_DIR) / "plot_study.py";
  // The script on study.csv, drawing into OUT/png; each chart adds its own options.
  const auto draw = [&](const char* png) {
    return "/usr/bin/python3 " + quote(script.string()) + " " +
           quote((out / "study.csv").string()) + " -o " + quote((out / png).string());
  };
  std::string cmd = draw("study.png");
  if (!study.plot_metric.empty()) cmd += " --metric " + quote(study.plot_metric);
  if (!study.plot_series.empty()) cmd += " --series " + quote(study.plot_series);
  if (!study.plot_label.empty()) cmd += " --label " + quote(study.plot_label);
  if (!study.reference_point.empty()) cmd += " --reference " + quote(study.reference_point);
  std::vector<std::pair<std::string, std::string>> charts;
  if (has_metrics)
    charts.emplace_back("study.png", cmd);
  else if (!quiet)
    std::printf(
        "isphdem study: no point reported an error against an expected value: no study.png\n");
  if (!study.stability.empty()) {
    std::string map = draw("stability.png") + " --stability " + quote(study.stability[0]) + " " +
                      quote(study.stability[1]);
    // One panel per series value (a map per model), unless the series is an axis of the map.
    if (!study.plot_series.empty() && study.plot_series != study.stability[0] &&
        study.plot_series != study.stability[1])
      map += " --series " + quote(study.plot_series);
    charts.emplace_back("stability.png", map);
  }
  if (!study.convergence.empty())
    charts.emplace_back("convergence.png",
                        draw("convergence.png") + " --convergence " + quote(study.convergence));
  for (auto& [png, command] : charts) {
    if (quiet) command += " > /dev/null";
    if (!fs::exists("/usr/bin/python3") || !fs::exists(script) || std::system(command.c_str()) != 0)
      std::fprintf(stderr,
                   "isphdem study: %s not drawn (scripts/plot_study.py failed, or "
                   "/usr/bin/python3 with matplotlib is missing: bash scripts/setup.sh); "
                   "study.csv is complete\n",
                   png.c_str());
  }
}

}  // namespace

int study_main(int argc, char** argv, const std::vector<std::string>& known_keys) {
  if (argc >= 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")) {
    std::printf("%s\n%s", kUsage, study_file_help());
    return 0;
  }
  try {
    const Arguments args = parse(argc, argv);
    const VerbArguments& a = args.verb;
    const Study study = load_study(a.file, a.overrides, known_keys);
    StudyRunOptions options;
    options.out = a.out;
    options.isphdem = fs::read_symlink("/proc/self/exe");
    options.jobs = args.jobs;
    options.quiet = a.quiet;
    if (!a.quiet) {
      std::printf("isphdem study: %s: %zu points of %s, %d at a time, into %s\n",
                  a.file.string().c_str(), study.points.size(), study.base.string().c_str(),
                  args.jobs, a.out.string().c_str());
      std::fflush(stdout);
    }
    fs::create_directories(a.out);
    auto outcomes = run_study(study, options);
    compare_with_reference_point(study, outcomes);
    write_study_table(a.out / "study.csv", study, outcomes);
    bool has_metrics = false;
    // study.png draws errors: metrics with no expected value and no reference point have none.
    for (const auto& o : outcomes)
      for (const auto& m : o.result.metrics) has_metrics = has_metrics || std::isfinite(m.error);
    plot(study, a.out, a.quiet, has_metrics);
    std::map<std::string, int> count;
    double wall = 0.0;
    for (const auto& o : outcomes) {
      ++count[o.status];
      if (!o.earlier) wall += o.result.wall_seconds;
    }
    if (!a.quiet) {
      std::string summary;
      for (const auto& [status, n] : count)
        summary += (summary.empty() ? "" : ", ") + std::to_string(n) + " " + status;
      std::printf("done: %zu points (%s), %s of point wall time; %s\n", outcomes.size(),
                  summary.c_str(), format_duration(wall).c_str(),
                  (a.out / "study.csv").string().c_str());
    }
    return 0;
  } catch (const CaseError& e) {
    std::fprintf(stderr, "isphdem study: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "isphdem study: %s\n", e.what());
    return 1;
  }
}

}  // namespace isphdem
