// Manufactured solutions of Biot's equations with a cohesive interface (order_mms_exact.hpp,
// order_mms.hpp): the plane x = 1/2 splits the unit square or cube, the interface closed and
// sticking (compressed, friction that never slips), mechanics only (impervious, no p3) or with
// the three-node flow (p3, transversal exchanges, longitudinal flow). Side 2's fields differ
// from side 1's by the jump the interface laws give for side 1's traction and flux, so that the
// interface terms of Problem (src/assembly/interface_assembly.cpp) act exactly as in a run.
// The meshes are distorted by the smooth map and jittered by a seeded pseudo-random amount of
// up to 0.15 h at every interior vertex (on the interface only along it). Besides the bulk
// rates (order_mms.hpp): the gap u2 - u1 and p3 in L2 on the interface at its integration
// points, and every point in the closed sticking state.
// Expected: the bulk rates of test_order_mms.cpp; P2 u in L2 3 only without flow and with
// alpha = 0 (p3, linear, pushes both faces and couples u to the pressure like alpha grad p).
#include "order_mms.hpp"

#include <gtest/gtest.h>

namespace {

using namespace poroseam::test_support;

// The axisymmetric interface cases run both orders (quadratic interfaces in axisymmetry:
// docs/elements.md); 1 would restrict them to order 1.
constexpr int kAxisymmetricInterfaceMaxOrder = 2;

constexpr double kJitter = 0.15; ///< of h, as in test_order_mms.cpp

class OrderMmsInterface : public ::testing::TestWithParam<Case> {};

TEST_P(OrderMmsInterface, RatesMatchTheElementOrder)
{
  checkRates(GetParam());
}

INSTANTIATE_TEST_SUITE_P(
    Meshes, OrderMmsInterface,
    ::testing::Values(
        Case{2, false, 0.8, {8, 16, 32}, false, Seam::flow, kJitter},
        Case{2, true, 0.8, {8, 16, 32}, false, Seam::flow, kJitter},
        Case{2, true, 0.0, {8, 16, 32}, false, Seam::mechanical, kJitter},
        Case{2, false, 0.0, {8, 16, 32}, false, Seam::mechanical, kJitter},
        Case{3, false, 0.8, {2, 4, 8}, false, Seam::flow, kJitter},
        Case{3, true, 0.8, {2, 4, 8}, false, Seam::flow, kJitter},
        Case{2, true, 0.8, {8, 16, 32}, true, Seam::flow, kJitter, kAxisymmetricInterfaceMaxOrder},
        Case{2, false, 0.8, {8, 16, 32}, true, Seam::flow, kJitter, kAxisymmetricInterfaceMaxOrder},
        // The nodal rule (trapezoid / Simpson on the faces' nodes; lumped ring weights).
        Case{2, false, 0.8, {8, 16, 32}, false, Seam::flow, kJitter, 2, true},
        Case{2,
             false,
             0.8,
             {8, 16, 32},
             true,
             Seam::flow,
             kJitter,
             kAxisymmetricInterfaceMaxOrder,
             true}),
    [](const ::testing::TestParamInfo<Case> &info) { return caseName(info.param); });

} // namespace
