// SIGINT and SIGTERM during a long run (Ctrl-C, a batch system's time limit): the first signal asks
// the run to stop at its next safe point, keeping what has converged (a nonlinear analysis stops
// its Newton step, keeps the converged load steps in curve.csv and writes its summary saying so);
// a second signal ends the process at once, as without this guard.
#pragma once

#include <deal.II/base/mpi.h>

#include <csignal>
#include <string>

namespace compliant
{
  class InterruptionGuard
  {
  public:
    InterruptionGuard();  // installs the handlers
    ~InterruptionGuard(); // restores the previous ones
    InterruptionGuard(const InterruptionGuard &) = delete;
    InterruptionGuard &operator=(const InterruptionGuard &) = delete;

    // Collective: true on every rank once any rank has received a signal.
    bool requested(MPI_Comm communicator) const;
    // The signal's name ("SIGTERM") and the exit code that reports it (128 + number).
    std::string signal_name(MPI_Comm communicator) const;
    int         exit_code(MPI_Comm communicator) const;

  private:
    struct sigaction previous_interrupt, previous_terminate;
  };
} // namespace compliant
