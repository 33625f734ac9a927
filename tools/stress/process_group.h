#pragma once
// The processes a stress campaign is spread over: this process alone, or the ranks of an MPI
// job started by mpirun (or srun). Two implementations, chosen by the DASHBED_MPI build option:
// process_group_mpi.cpp (OpenMPI) and process_group_single.cpp (no MPI in the build).

#include <cstdlib>
#include <string>
#include <vector>

namespace dashbed::tools {

/// True when an MPI launcher started this process (it sets these variables for every rank).
inline bool launchedByMpi() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMIX_RANK") != nullptr ||
         std::getenv("PMI_RANK") != nullptr;
}

class ProcessGroup {
 public:
  /// Joins the MPI job when launchedByMpi(), else a group of this process alone. Throws
  /// std::invalid_argument when launched by MPI but built without it (every rank would
  /// otherwise run the whole campaign and write the same files).
  ProcessGroup();
  ~ProcessGroup();  ///< leaves the MPI job (MPI_Finalize)
  ProcessGroup(const ProcessGroup&) = delete;
  ProcessGroup& operator=(const ProcessGroup&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  /// Ranks of the job on this machine (for sharing its cores); 1 without MPI.
  int localSize() const { return local_size_; }

  /// Every rank's `local`, in rank order, on rank 0; empty on the others. Collective: every
  /// rank must call it.
  std::vector<std::string> gatherToRoot(const std::string& local) const;

  /// Ends the whole job with `code` (MPI_Abort), for an error that hit this rank alone and
  /// would leave the others waiting; without MPI, std::exit(code).
  [[noreturn]] void abort(int code) const;

 private:
  int rank_ = 0;
  int size_ = 1;
  int local_size_ = 1;
  bool joined_ = false;
};

}  // namespace dashbed::tools
