// mobb graph / crowd / bench: registered here once the crowd layer provides them.
#include "cli.h"

namespace mobb::app {

void add_crowd_commands(CLI::App&, int&) {}

}  // namespace mobb::app
