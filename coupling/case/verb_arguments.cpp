#include "case/verb_arguments.hpp"

#include "case/case_file.hpp"

namespace isphdem {

VerbArguments parse_verb_arguments(int argc, char** argv, const std::string& file_kind,
                                   const std::string& usage, const VerbOption& extra) {
  VerbArguments a;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const std::function<std::string()> value = [&]() -> std::string {
      if (i + 1 >= argc) throw CaseError(arg + " needs a value\n" + usage);
      return argv[++i];
    };
    if (extra && extra(arg, value)) continue;
    if (arg == "--out")
      a.out = value();
    else if (arg == "--set")
      a.overrides.push_back(value());
    else if (arg.rfind("--set=", 0) == 0)
      a.overrides.push_back(arg.substr(6));
    else if (arg == "--quiet")
      a.quiet = true;
    else if (arg.rfind("-", 0) == 0)
      throw CaseError("unknown option '" + arg + "'\n" + usage);
    else if (a.file.empty())
      a.file = arg;
    else
      throw CaseError("more than one " + file_kind + " given ('" + a.file.string() + "', '" + arg +
                      "')");
  }
  if (a.file.empty()) throw CaseError("no " + file_kind + " given\n" + usage);
  if (a.out.empty()) throw CaseError("no output directory given (--out DIR)\n" + usage);
  return a;
}

}  // namespace isphdem
