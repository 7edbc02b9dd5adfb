// Manufactured solutions of Biot's equations at displacement orders 1 and 2 on distorted
// meshes (order_meshes.hpp): observed rates of convergence in L2 and energy norms. The
// framework (fields, forcing, solve, errors, expected rates) is order_mms.hpp; the cases with a
// cohesive interface are test_order_mms_interface.cpp.
#include "order_mms.hpp"

#include <gtest/gtest.h>

namespace {

using namespace poroseam::test_support;

class OrderMms : public ::testing::TestWithParam<Case> {};

TEST_P(OrderMms, RatesMatchTheElementOrder)
{
  checkRates(GetParam());
}

INSTANTIATE_TEST_SUITE_P(
    Meshes, OrderMms,
    ::testing::Values(Case{2, false, 0.8, {8, 16, 32}}, Case{2, true, 0.8, {8, 16, 32}},
                      Case{2, false, 0.0, {8, 16, 32}}, Case{2, true, 0.0, {8, 16, 32}},
                      Case{3, false, 0.8, {2, 4, 8}}, Case{3, true, 0.8, {2, 4, 8}},
                      Case{2, true, 0.0, {8, 16, 32}, true}, Case{2, false, 0.0, {8, 16, 32}, true},
                      Case{2, true, 0.8, {8, 16, 32}, true}),
    [](const ::testing::TestParamInfo<Case> &info) { return caseName(info.param); });

} // namespace
