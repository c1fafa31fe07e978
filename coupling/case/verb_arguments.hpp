#pragma once
// The command line every verb shares: isphdem <verb> FILE --out DIR [--set key=value ...]
// [--quiet], plus the options of one verb. CaseError (with the usage) for anything else.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace isphdem {

struct VerbArguments {
  std::filesystem::path file;
  std::filesystem::path out;
  std::vector<std::string> overrides;
  bool quiet = false;
};

// `extra(arg, value)` sees every option first and returns true when it is the verb's own;
// value() takes the next argument (CaseError naming the option when there is none).
using VerbOption =
    std::function<bool(const std::string& arg, const std::function<std::string()>& value)>;

// `file_kind` names FILE in messages ("case file", "study file").
VerbArguments parse_verb_arguments(int argc, char** argv, const std::string& file_kind,
                                   const std::string& usage, const VerbOption& extra = {});

}  // namespace isphdem
