// PLACEHOLDER for the dem branch only (the lead's run_command.hpp replaces it at merge).
#ifndef ISPHDEM_RUN_COMMAND_HPP
#define ISPHDEM_RUN_COMMAND_HPP

namespace isphdem {
int run_main(int argc, char** argv);
}

#endif
