// Internal: the stages of the exact 5-point power test after the inline double filter, exposed
// for tests that check each stage against exact expansion arithmetic. Each returns the power test
// sign (predicates.h convention) or 2 when it cannot decide. `pts` are p, q, r, s (4 doubles each).
#pragma once

namespace delpsc::kernel::detail {

/// Exact in 128-bit integers when every difference is a small integer (else 2).
int power_test_integer(const double* const pts[4], const double* t, bool weighted);
/// Double-double evaluation with a rigorous error bound (2 when inside the bound).
int power_test_double_double(const double* const pts[4], const double* t, bool weighted);
/// Exact expansion arithmetic; always decides.
int power_test_expansion(const double* const pts[4], const double* t, bool weighted);

}  // namespace delpsc::kernel::detail
