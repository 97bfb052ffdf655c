// The linear solver a case asks for ('Linear solver/Method') and the one a problem settles on.
// Parsed once from the case file; below input/ only the enum is compared, never its text.
#pragma once

#include <stdexcept>
#include <string>

namespace compliant
{
  enum class SolverMethod
  {
    automatic,   // 'auto': the problem chooses (README, "Linear solvers")
    matrix_free, // CG with the matrix-free p-multigrid
    cg_amg,      // CG + GAMG on the assembled matrix
    direct       // MUMPS LU
  };

  inline std::string to_string(const SolverMethod method)
  {
    switch (method)
      {
        case SolverMethod::automatic: return "auto";
        case SolverMethod::matrix_free: return "matrix-free";
        case SolverMethod::cg_amg: return "cg-amg";
        case SolverMethod::direct: return "direct";
      }
    return "?";
  }

  // The case file's text; throws std::invalid_argument for anything else (the parameter's pattern
  // refuses it first, so this guards programming errors only).
  inline SolverMethod solver_method_from_string(const std::string &text)
  {
    for (const auto method : {SolverMethod::automatic, SolverMethod::matrix_free, SolverMethod::cg_amg,
                              SolverMethod::direct})
      if (to_string(method) == text)
        return method;
    throw std::invalid_argument("linear solver method '" + text + "': expected auto, matrix-free, cg-amg or direct");
  }
} // namespace compliant
