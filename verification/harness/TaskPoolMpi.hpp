#pragma once
// run_tasks across the ranks of an MPI job (see TaskPool.hpp): the coordinator's loop and the
// other ranks' loop. Built only with MPI; without it this throws (Ensemble::size() is then 1 and
// run_tasks never calls it).
#include "verification/harness/TaskPool.hpp"

namespace vorodg {

void run_tasks_mpi(const std::vector<Task>& tasks, int threads,
                   const std::function<TaskOutput(const Task&)>& execute,
                   const std::function<void(const Task&, const TaskOutput&)>& record);

}  // namespace vorodg
