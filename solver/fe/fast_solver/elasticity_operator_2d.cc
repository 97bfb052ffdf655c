// One dimension per translation unit: the degree 1-4 kernels compile slowly.
#include "fast_solver/elasticity_operator.templates.h"

template class compliant::fast_solver::ElasticityOperator<2, double>;
