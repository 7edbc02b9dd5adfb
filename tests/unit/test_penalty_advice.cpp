// The penalty-range advice of docs/interface_parameters.md: beta = K h / E against the softer
// side for overlap, against the stiffer side for conditioning.
#include "poroseam/penalty_advice.hpp"

#include <gtest/gtest.h>

using poroseam::advisePenalty;
using poroseam::PenaltyVerdict;

TEST(PenaltyAdvice, CaissonParametersAreFine)
{
  // The paper's K = 1e10 Pa/m next to soil (E = 2e8 Pa) and steel (2e11) at h = 0.1 m:
  // K h / E = 5 against the soil, 5e-3 against the steel.
  EXPECT_EQ(advisePenalty(1e10, 0.1, 2e8, 2e11), PenaltyVerdict::fine);
}

TEST(PenaltyAdvice, SoftWhenTheInterfaceIsAsCompliantAsAnElement)
{
  // The boundary of the range is K h / E_soft = 1 exactly.
  EXPECT_EQ(advisePenalty(0.99e9, 0.1, 1e8, 1e8), PenaltyVerdict::too_soft);
  EXPECT_EQ(advisePenalty(1.01e9, 0.1, 1e8, 1e8), PenaltyVerdict::fine);
  // Softness is judged against the softer body, whatever the stiffer one is.
  EXPECT_EQ(advisePenalty(1e8, 0.1, 2e8, 2e11), PenaltyVerdict::too_soft);
}

TEST(PenaltyAdvice, StiffWhenThePenaltyDominatesTheStiffestNeighbour)
{
  EXPECT_EQ(advisePenalty(1.01e15, 0.1, 1e10, 1e10), PenaltyVerdict::too_stiff);
  EXPECT_EQ(advisePenalty(0.99e15, 0.1, 1e10, 1e10), PenaltyVerdict::fine);
  // Against soft soil beside steel, the steel's rows set the conditioning limit.
  EXPECT_EQ(advisePenalty(1e14, 0.1, 2e8, 2e11), PenaltyVerdict::fine);
}

TEST(PenaltyAdvice, NoVerdictWithoutGeometryOrMaterial)
{
  EXPECT_EQ(advisePenalty(0.0, 0.1, 1e8, 1e8), PenaltyVerdict::fine);
  EXPECT_EQ(advisePenalty(1e10, 0.0, 1e8, 1e8), PenaltyVerdict::fine);
  EXPECT_EQ(advisePenalty(1e10, 0.1, 0.0, 1e8), PenaltyVerdict::fine);
}
