// Work that may crash, hang or exhaust memory on user input (gmsh on a .geo file) runs in a forked
// child process under a memory cap and a wall-clock limit. The caller gets the bytes the work
// returned, or one exception saying what went wrong; its own state (MPI, the heap, a library's
// globals) is untouched, since the child never returns to the caller's code: it leaves by _exit.
// Fork rather than spawning a helper binary: every program linking the mesh code (the solver, the
// section solver, the test programs) gets the containment without a second entry point, and Open
// MPI (shared memory and TCP transports) tolerates a child that never calls MPI.
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>

namespace compliant
{
  struct ContainmentLimits
  {
    // Bytes of address space the child may add to what it inherits from its parent: it starts
    // capped at initial_memory and may lift the cap to memory (extend_contained_limits). 0: no cap.
    std::uint64_t initial_memory = 0;
    std::uint64_t memory         = 0;
    unsigned int  seconds        = 0; // wall clock from the start; 0: no limit
  };

  // How a contained call failed. error: the work threw, what() is its message. Otherwise what()
  // says how the child ended, e.g. "crashed (segmentation fault) while meshing the surfaces",
  // "ran out of memory (cap 1.0 GB) while meshing the curves", "did not finish within 60 s".
  struct ContainedCallFailed : std::runtime_error
  {
    enum Kind
    {
      error,
      crashed,
      out_of_memory,
      timed_out
    };
    ContainedCallFailed(const Kind kind, const std::string &what)
      : std::runtime_error(what)
      , kind(kind)
    {}
    Kind kind;
  };

  // Runs work() in a forked child and returns what it returned. work must not call MPI (the
  // child is not an MPI process). Throws ContainedCallFailed.
  std::string call_contained(const std::function<std::string()> &work, const ContainmentLimits &limits);

  // Inside work(): names the stage the work is in, for a failure message ("meshing the curves").
  void set_contained_stage(const std::string &stage);

  // Inside work(), once it knows how big its job is: lifts the memory cap to limits.memory and
  // restarts the clock with `seconds` (0: keep the running limit). Outside one, does nothing.
  void extend_contained_limits(unsigned int seconds);
} // namespace compliant
