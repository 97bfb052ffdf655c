// The Gauss rules a matrix-free kernel runs with, shared by the small-strain and the finite-strain
// operators: the full rule (p + 1 points per direction, MatrixFree rule 0) alone, or with
// Discretization/Integration = reduced also the reduced one (p points, rule 1), each with its share
// of K = (1 - e) K_p + e K_(p+1) (discretization/reduced_integration.h).
#pragma once

#include <stdexcept>
#include <string>

namespace compliant::fast_solver
{
  // Kernel<dim, degree, n_q, Number> has members `quad` (the MatrixFree rule) and `scale` (its share).
  // Runs visitor(kernel) for each rule of the run-time degree (1-4: the element degrees offered).
  template <template <int, int, int, typename> class Kernel, int dim, typename Number, typename Visitor>
  void for_each_rule(const unsigned int degree, const bool reduced, const double hourglass, const Visitor &visitor,
                     const char *what = "matrix-free operator")
  {
    const auto run = [&](auto full, auto reduced_rule) {
      full.scale = reduced ? hourglass : 1;
      visitor(full);
      if (reduced)
        {
          reduced_rule.quad  = 1;
          reduced_rule.scale = 1 - hourglass;
          visitor(reduced_rule);
        }
    };
    switch (degree)
      {
        case 1: run(Kernel<dim, 1, 2, Number>(), Kernel<dim, 1, 1, Number>()); break;
        case 2: run(Kernel<dim, 2, 3, Number>(), Kernel<dim, 2, 2, Number>()); break;
        case 3: run(Kernel<dim, 3, 4, Number>(), Kernel<dim, 3, 3, Number>()); break;
        case 4: run(Kernel<dim, 4, 5, Number>(), Kernel<dim, 4, 4, Number>()); break;
        default:
          throw std::invalid_argument(std::string(what) + ": element degree " + std::to_string(degree) +
                                      " is not compiled (1-4)");
      }
  }
} // namespace compliant::fast_solver
