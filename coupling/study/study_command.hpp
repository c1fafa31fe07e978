#pragma once
#include <string>
#include <vector>

namespace isphdem {

// isphdem study STUDY.toml --out DIR [-j N] [--set key=value ...] [--quiet]. `known_keys` are
// the keys a case may hold (the study checks every point's case against them before it starts).
// Exit status: 0 when every point was run or recorded (points that failed included), 2 for a bad
// study file or arguments.
int study_main(int argc, char** argv, const std::vector<std::string>& known_keys);

}  // namespace isphdem
