// The group of hermite_tests on the reference shape functions, defined in
// hermite_test_reference.cc: Kronecker conditions, membership of the 12-term
// space of eq. 22, agreement with the paper's printed eq. 23-25, finite
// differences of the gradients and Hessians, partition of unity.
#pragma once

#include "hermite_test_tools.h"

namespace hermite_tests
{
  void
  test_reference_functions(Checker &check, Random &random);
} // namespace hermite_tests
