#include "mesh/contained_call.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <new>
#include <sstream>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace compliant
{
  namespace
  {
    // What the child tells the parent besides its result: where it was and what limits it ran
    // under when it ended. In a shared mapping, so that it survives a crash.
    struct SharedStatus
    {
      char          stage[120];
      unsigned int  seconds;
      std::uint64_t memory_cap;
    };

    // The child's view of its own call; null in the parent.
    struct ChildState
    {
      SharedStatus     *status;
      ContainmentLimits limits;
      std::uint64_t     inherited_memory; // address space at the fork
      int               fd;               // write end of the result pipe
    };
    ChildState *child = nullptr;

    std::uint64_t virtual_memory_size()
    {
      std::ifstream status("/proc/self/status");
      std::string   key;
      while (status >> key)
        {
          if (key == "VmSize:")
            {
              std::uint64_t kilobytes = 0;
              status >> kilobytes;
              return kilobytes * 1024;
            }
          status.ignore(1 << 12, '\n');
        }
      return 0;
    }

    // The cap counts the parent's mappings too (the child inherits them): offset it by them.
    void cap_address_space(const std::uint64_t soft, const std::uint64_t hard)
    {
      if (hard == 0)
        return;
      rlimit limit;
      limit.rlim_cur = child->inherited_memory + soft;
      limit.rlim_max = child->inherited_memory + hard;
      setrlimit(RLIMIT_AS, &limit);
    }

    bool write_all(const int fd, const char *data, std::size_t size)
    {
      while (size > 0)
        {
          const ssize_t written = write(fd, data, size);
          if (written < 0 && errno == EINTR)
            continue;
          if (written <= 0)
            return false;
          data += written;
          size -= static_cast<std::size_t>(written);
        }
      return true;
    }

    [[noreturn]] void report_and_exit(const char tag, const std::string &payload)
    {
      const bool sent = write_all(child->fd, &tag, 1) && write_all(child->fd, payload.data(), payload.size());
      _exit(sent ? 0 : 3);
    }

    // An allocation failing inside a region that cannot throw (gmsh's OpenMP loops) ends in
    // std::terminate: still say it was memory.
    [[noreturn]] void on_terminate()
    {
      try
        {
          if (std::current_exception())
            std::rethrow_exception(std::current_exception());
        }
      catch (const std::bad_alloc &)
        {
          report_and_exit('M', "");
        }
      catch (...)
        {
        }
      signal(SIGABRT, SIG_DFL);
      abort();
    }

    [[noreturn]] void run_child(const std::function<std::string()> &work)
    {
      // The parent's handlers (Open MPI prints a stack dump on SIGSEGV) are not the child's: a
      // crash must end it quietly, for the parent to report.
      for (const int s : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGALRM, SIGTERM, SIGPIPE, SIGINT})
        signal(s, SIG_DFL);
      sigset_t all;
      sigfillset(&all);
      sigprocmask(SIG_UNBLOCK, &all, nullptr);
      const rlimit no_core = {0, 0};
      setrlimit(RLIMIT_CORE, &no_core);
      std::set_terminate(on_terminate);
      child->inherited_memory = virtual_memory_size();
      cap_address_space(child->limits.initial_memory ? child->limits.initial_memory : child->limits.memory,
                        child->limits.memory);
      alarm(child->limits.seconds);
      try
        {
          report_and_exit('R', work());
        }
      catch (const std::bad_alloc &)
        {
          report_and_exit('M', "");
        }
      catch (const std::exception &e)
        {
          report_and_exit('E', e.what());
        }
      catch (...)
        {
          report_and_exit('E', "unknown error");
        }
    }

    std::string read_all(const int fd)
    {
      std::string text;
      char        buffer[1 << 16];
      while (true)
        {
          const ssize_t got = read(fd, buffer, sizeof buffer);
          if (got < 0 && errno == EINTR)
            continue;
          if (got <= 0)
            return text;
          text.append(buffer, static_cast<std::size_t>(got));
        }
    }

    std::string gigabytes(const std::uint64_t bytes)
    {
      std::ostringstream text;
      text.precision(2);
      text << bytes / 1e9 << " GB";
      return text.str();
    }

    // The child ended without a result: say how, and where it was.
    ContainedCallFailed describe_end(const int status, const rusage &usage, const SharedStatus &shared)
    {
      const std::string where      = shared.stage[0] ? std::string(" while ") + shared.stage : "";
      const double      peak_bytes = 1024.0 * usage.ru_maxrss;
      const bool        near_cap   = shared.memory_cap > 0 && peak_bytes > 0.5 * shared.memory_cap;
      const std::string cap_note =
        near_cap ? " near its memory cap of " + gigabytes(shared.memory_cap) + (where.empty() ? "" : ",") : "";
      if (WIFSIGNALED(status))
        {
          const int signal_number = WTERMSIG(status);
          if (signal_number == SIGALRM)
            return {ContainedCallFailed::timed_out,
                    "did not finish within " + std::to_string(shared.seconds) + " s" + where};
          if (signal_number == SIGKILL)
            return {ContainedCallFailed::out_of_memory,
                    "was killed (signal 9, most likely by the kernel for lack of memory)" + where};
          std::string name = strsignal(signal_number);
          for (auto &c : name)
            c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
          return {near_cap ? ContainedCallFailed::out_of_memory : ContainedCallFailed::crashed,
                  "crashed (" + name + ")" + cap_note + where};
        }
      return {near_cap ? ContainedCallFailed::out_of_memory : ContainedCallFailed::crashed,
              "stopped with exit code " + std::to_string(WEXITSTATUS(status)) + cap_note + where};
    }
  } // namespace

  void set_contained_stage(const std::string &stage)
  {
    if (!child)
      return;
    const std::size_t n = std::min(stage.size(), sizeof child->status->stage - 1);
    std::memcpy(child->status->stage, stage.data(), n);
    child->status->stage[n] = '\0';
  }

  void extend_contained_limits(const unsigned int seconds)
  {
    if (!child)
      return;
    cap_address_space(child->limits.memory, child->limits.memory);
    child->status->memory_cap = child->limits.memory;
    if (seconds > 0)
      {
        child->status->seconds = seconds;
        alarm(seconds);
      }
  }

  std::string call_contained(const std::function<std::string()> &work, const ContainmentLimits &limits)
  {
    void *mapping = mmap(nullptr, sizeof(SharedStatus), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    if (mapping == MAP_FAILED)
      throw std::runtime_error(std::string("cannot set up a child process: ") + std::strerror(errno));
    auto *shared = new (mapping) SharedStatus{};
    shared->seconds    = limits.seconds;
    shared->memory_cap = limits.initial_memory ? limits.initial_memory : limits.memory;
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0)
      {
        munmap(mapping, sizeof(SharedStatus));
        throw std::runtime_error(std::string("cannot set up a child process: ") + std::strerror(errno));
      }
    // Buffered output would otherwise be written twice, once by each process.
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    const pid_t pid = fork();
    if (pid == 0)
      {
        close(fds[0]);
        ChildState state{shared, limits, 0, fds[1]};
        child = &state;
        run_child(work);
      }
    close(fds[1]);
    if (pid < 0)
      {
        close(fds[0]);
        munmap(mapping, sizeof(SharedStatus));
        throw std::runtime_error(std::string("cannot start a child process: ") + std::strerror(errno));
      }
    const std::string message = read_all(fds[0]);
    close(fds[0]);
    int    status = 0;
    rusage usage{};
    pid_t  waited;
    do
      waited = wait4(pid, &status, 0, &usage);
    while (waited < 0 && errno == EINTR);
    const SharedStatus final_status = *shared;
    munmap(mapping, sizeof(SharedStatus));

    // A complete report counts even if someone else reaped the child (waited < 0: ECHILD).
    const bool clean_exit = waited < 0 || (WIFEXITED(status) && WEXITSTATUS(status) == 0);
    if (clean_exit && !message.empty())
      {
        if (message[0] == 'R')
          return message.substr(1);
        if (message[0] == 'E')
          throw ContainedCallFailed(ContainedCallFailed::error, message.substr(1));
        if (message[0] == 'M')
          throw ContainedCallFailed(ContainedCallFailed::out_of_memory,
                                    "ran out of memory (cap " + gigabytes(final_status.memory_cap) + ")" +
                                      (final_status.stage[0] ? std::string(" while ") + final_status.stage : ""));
      }
    if (waited < 0)
      throw ContainedCallFailed(ContainedCallFailed::crashed, "ended without a result");
    throw describe_end(status, usage, final_status);
  }
} // namespace compliant
