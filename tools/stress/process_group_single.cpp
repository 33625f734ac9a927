// ProcessGroup without MPI (DASHBED_MPI off): this process alone.

#include <stdexcept>

#include "tools/stress/process_group.h"

namespace dashbed::tools {

ProcessGroup::ProcessGroup() {
  if (launchedByMpi()) {
    throw std::invalid_argument(
        "started by an MPI launcher, but this dashbed was built without MPI: configure with -DDASHBED_MPI=ON "
        "(tools/setup.sh does) or run it without mpirun");
  }
}

ProcessGroup::~ProcessGroup() = default;

std::vector<std::string> ProcessGroup::gatherToRoot(const std::string& local) const { return {local}; }

void ProcessGroup::abort(int code) const { std::exit(code); }

}  // namespace dashbed::tools
