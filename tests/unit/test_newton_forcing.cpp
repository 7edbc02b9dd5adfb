// The linear tolerance of a Newton solve (include/poroseam/newton_forcing.hpp): each regime
// of the rule, checked against its definition.
#include "poroseam/newton_forcing.hpp"

#include <gtest/gtest.h>

using poroseam::linearTolerance;

// A linear problem converges in its first Newton iteration: nothing is known and nothing is
// loosened, the solve goes to -ksp_rtol.
TEST(NewtonForcing, NothingKnownGivesTheFloor)
{
  EXPECT_DOUBLE_EQ(linearTolerance(1e-8, 0.0, 0.0), 1e-8);
}

// Close to the end: a hundred times below the target is enough.
TEST(NewtonForcing, TargetWithinReach)
{
  EXPECT_DOUBLE_EQ(linearTolerance(1e-8, 1e-2, 0.0), 1e-4);
  EXPECT_DOUBLE_EQ(linearTolerance(1e-8, 1e-2, 1e-6), 1e-4);
}

// A Newton iteration that reduced the residual only by c: the next solve to c / 10.
TEST(NewtonForcing, NonlinearityDominates)
{
  EXPECT_DOUBLE_EQ(linearTolerance(1e-8, 1e-9, 2.5e-3), 2.5e-4);
  EXPECT_DOUBLE_EQ(linearTolerance(1e-8, 0.0, 2.5e-5), 2.5e-6);
}

// Never looser than 0.01 (a residual that grew, or a target already met), never tighter than
// the floor.
TEST(NewtonForcing, Bounds)
{
  EXPECT_DOUBLE_EQ(linearTolerance(1e-8, 0.0, 2.0), 0.01);
  EXPECT_DOUBLE_EQ(linearTolerance(1e-8, 50.0, 0.0), 0.01);
  EXPECT_DOUBLE_EQ(linearTolerance(1e-3, 1e-9, 1e-9), 1e-3);
  EXPECT_DOUBLE_EQ(linearTolerance(1e-8, -1.0, -1.0), 1e-8);
}
