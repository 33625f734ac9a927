// ProcessGroup on MPI (DASHBED_MPI on). MPI is initialised only when an MPI launcher started
// the process, so the same binary also runs on its own.

#include <limits>
#include <stdexcept>

#include <mpi.h>

#include "tools/stress/process_group.h"

namespace dashbed::tools {

ProcessGroup::ProcessGroup() {
  if (!launchedByMpi()) return;
  // worker threads never call MPI: only the main thread does
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  joined_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node);
  MPI_Comm_size(node, &local_size_);
  MPI_Comm_free(&node);
}

ProcessGroup::~ProcessGroup() {
  if (joined_) MPI_Finalize();
}

std::vector<std::string> ProcessGroup::gatherToRoot(const std::string& local) const {
  if (!joined_) return {local};
  if (local.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw std::runtime_error("MPI gather: rank " + std::to_string(rank_) + " has more than 2 GB of results");
  }
  int length = static_cast<int>(local.size());
  std::vector<int> lengths(static_cast<std::size_t>(rank_ == 0 ? size_ : 0));
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<int> offsets(lengths.size());
  long long total = 0;
  for (std::size_t r = 0; r < lengths.size(); ++r) {
    offsets[r] = static_cast<int>(total);
    total += lengths[r];
  }
  if (total > std::numeric_limits<int>::max()) throw std::runtime_error("MPI gather: more than 2 GB of results");
  std::string all(static_cast<std::size_t>(total), '\0');
  MPI_Gatherv(local.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, 0, MPI_COMM_WORLD);
  std::vector<std::string> parts;
  for (std::size_t r = 0; r < lengths.size(); ++r) {
    parts.push_back(all.substr(static_cast<std::size_t>(offsets[r]), static_cast<std::size_t>(lengths[r])));
  }
  return parts;
}

void ProcessGroup::abort(int code) const {
  if (joined_) MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

}  // namespace dashbed::tools
