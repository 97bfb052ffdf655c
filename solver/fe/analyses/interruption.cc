#include "analyses/interruption.h"

#include <cstring>

namespace compliant
{
  namespace
  {
    volatile std::sig_atomic_t received_signal = 0;

    extern "C" void note_signal(const int number)
    {
      if (received_signal != 0)
        {
          // Second signal: the default action (end the process) now.
          std::signal(number, SIG_DFL);
          std::raise(number);
          return;
        }
      received_signal = number;
    }

    int agreed_signal(MPI_Comm communicator)
    {
      return dealii::Utilities::MPI::max(static_cast<int>(received_signal), communicator);
    }
  } // namespace

  InterruptionGuard::InterruptionGuard()
  {
    received_signal = 0;
    struct sigaction action;
    std::memset(&action, 0, sizeof(action));
    action.sa_handler = note_signal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &previous_interrupt);
    sigaction(SIGTERM, &action, &previous_terminate);
  }

  InterruptionGuard::~InterruptionGuard()
  {
    sigaction(SIGINT, &previous_interrupt, nullptr);
    sigaction(SIGTERM, &previous_terminate, nullptr);
  }

  bool InterruptionGuard::requested(MPI_Comm communicator) const
  {
    return agreed_signal(communicator) != 0;
  }

  std::string InterruptionGuard::signal_name(MPI_Comm communicator) const
  {
    const int number = agreed_signal(communicator);
    return number == SIGINT ? "SIGINT" : number == SIGTERM ? "SIGTERM" : "signal " + std::to_string(number);
  }

  int InterruptionGuard::exit_code(MPI_Comm communicator) const
  {
    return 128 + agreed_signal(communicator);
  }
} // namespace compliant
