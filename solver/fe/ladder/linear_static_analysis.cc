#include "ladder/linear_static_analysis.h"

#include "analyses/linear_static.h"
#include "ladder/model_ladder.h"
#include "ladder/paired_model.h"

#include <iostream>

namespace compliant
{
  namespace
  {
    int run(const RunContext &context)
    {
      const TargetSettings target = read_target_settings(const_cast<dealii::ParameterHandler &>(context.prm));
      const auto          &p      = context.parameters;
      if (target.relative_error > 0 && p.reduced_integration)
        throw InputError("case file '" + p.case_file + "', Discretization/Integration = reduced: the model "
                         "ladder (Target/Relative error > 0) compares fully integrated rungs; set one of them");
      if (target.relative_error > 0)
        return p.dimension == 2 ? run_model_ladder<2>(context, target) : run_model_ladder<3>(context, target);
      if (!target.paired_model.empty())
        {
          // Only the ladder reads the pair; --check still validates it.
          if (context.check_only)
            read_paired_model(p, context.geometry, target.paired_model, context.communicator);
          if (dealii::Utilities::MPI::this_mpi_process(context.communicator) == 0)
            std::cout << "Target/Paired model is read by the model ladder only (Target/Relative error "
                         "= 0 here): this run solves " << p.case_file << " as set\n";
        }
      return run_linear_static(context);
    }
  } // namespace

  Analysis linear_static_analysis()
  {
    return {{"linear static",
             "small-strain linear elasticity, one solve; with Target/Relative error > 0 the model "
             "ladder chooses the discretization and, if needed, finite strain",
             [](dealii::ParameterHandler &prm) { declare_target_settings(prm); }},
            run};
  }
} // namespace compliant
