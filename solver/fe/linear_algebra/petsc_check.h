// One error check for raw PETSc (and SLEPc) calls: our code throws where PETSc returns a code, so
// a failed call ends in the solver's error message instead of a half-built object.
#pragma once

#include <petscsys.h>

#include <stdexcept>
#include <string>

namespace compliant
{
  // check(ierr, "KSPSolve") throws std::runtime_error "<owner>: PETSc error in KSPSolve (code N)"
  // when ierr is not 0; owner names the solver or object being built.
  class PetscErrorCheck
  {
  public:
    explicit constexpr PetscErrorCheck(const char *owner_in)
      : owner(owner_in)
    {}
    void operator()(const PetscErrorCode ierr, const char *what) const
    {
      if (ierr != 0)
        throw std::runtime_error(std::string(owner) + ": PETSc error in " + what + " (code " +
                                 std::to_string(ierr) + ")");
    }

  private:
    const char *owner;
  };
} // namespace compliant
