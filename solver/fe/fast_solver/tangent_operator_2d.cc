// One dimension per translation unit: the degree 1-4 kernels compile slowly.
#include "fast_solver/tangent_operator.templates.h"

template class compliant::fast_solver::TangentOperator<2, double>;
