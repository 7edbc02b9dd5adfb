// Manufactured solutions of Biot's equations at displacement orders 1 and 2 on distorted
// meshes (order_meshes.hpp: a smooth map and a seeded pseudo-random jitter of every interior
// vertex, so cells are irregular and non-affine at every h): observed rates of convergence in
// L2 and energy norms. The
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

// Every mesh distorted by the smooth map and jittered by up to 0.15 h (order_meshes.hpp).
constexpr double kJitter = 0.15;

INSTANTIATE_TEST_SUITE_P(
    Meshes, OrderMms,
    ::testing::Values(Case{2, false, 0.8, {8, 16, 32}, false, Seam::none, kJitter},
                      Case{2, true, 0.8, {8, 16, 32}, false, Seam::none, kJitter},
                      Case{2, false, 0.0, {8, 16, 32}, false, Seam::none, kJitter},
                      Case{2, true, 0.0, {8, 16, 32}, false, Seam::none, kJitter},
                      Case{3, false, 0.8, {2, 4, 8}, false, Seam::none, kJitter},
                      Case{3, true, 0.8, {2, 4, 8}, false, Seam::none, kJitter},
                      Case{2, true, 0.0, {8, 16, 32}, true, Seam::none, kJitter},
                      Case{2, false, 0.0, {8, 16, 32}, true, Seam::none, kJitter},
                      Case{2, true, 0.8, {8, 16, 32}, true, Seam::none, kJitter}),
    [](const ::testing::TestParamInfo<Case> &info) { return caseName(info.param); });

} // namespace
