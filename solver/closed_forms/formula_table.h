// The table behind registry(): one entry per closed form, with its validity-range warnings.
#ifndef CLOSED_FORMS_FORMULA_TABLE_H
#define CLOSED_FORMS_FORMULA_TABLE_H

#include "registry.h"

#include <vector>

namespace closed_forms
{
  namespace internal
  {
    std::vector<Formula> make_formula_table();
  }
} // namespace closed_forms

#endif
