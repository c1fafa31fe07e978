#pragma once

namespace isphdem {

// `isphdem run CASE.toml --out DIR [--set key=value ...] [--quiet]`; argv[0] is "run".
int run_main(int argc, char** argv);

}  // namespace isphdem
