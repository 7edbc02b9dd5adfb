// Interface contact and Coulomb friction: closed-form paths (shear ramp, reversal, opening,
// oblique sliding) and the consistent tangent against finite differences in every state.
#include "poroseam/contact.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

using namespace poroseam::physics;

namespace {
const ContactParameters kParams{1e10, 1e9, 0.57};
const ContactInitial kInitial{0.0, 1e5}; // in contact at 100 kPa

ContactResponse at(const ContactHistory &h, int nt, double gn, double gt0, double gt1 = 0.0)
{
  const double gt[2] = {gt0, gt1};
  return contactResponse(kParams, kInitial, h, nt, gn, gt);
}
} // namespace

TEST(Contact, NormalPenaltyFromInitialState)
{
  ContactHistory h;
  // Closing by 1 um adds K_N * 1e-6 = 10 kPa.
  auto r = at(h, 1, -1e-6, 0.0);
  EXPECT_EQ(r.state, ContactState::stick);
  EXPECT_NEAR(r.contact_pressure_effective, 1.1e5, 1e-6);
  EXPECT_NEAR(r.tangent[0][0], -1e10, 1e-3);
  // Opening beyond p'_N0 / K_N = 10 um: open, no traction, opening = g_N - 10 um.
  r = at(h, 1, 2.5e-5, 3e-6);
  EXPECT_EQ(r.state, ContactState::open);
  EXPECT_EQ(r.contact_pressure_effective, 0.0);
  EXPECT_EQ(r.shear[0], 0.0);
  EXPECT_NEAR(mechanicalOpening(kParams, kInitial, 2.5e-5), 1.5e-5, 1e-18);
  EXPECT_EQ(mechanicalOpening(kParams, kInitial, 5e-6), 0.0);
}

TEST(Contact, ShearRampStickThenSlipThenElasticReversal)
{
  ContactHistory h;
  const double limit = 0.57 * 1e5;
  const double slip_onset = limit / 1e9; // g_T where tau reaches mu p'_N
  double gt = 0.0, tau_max = 0.0;
  for (int step = 1; step <= 40; ++step) {
    gt = step * 0.05 * slip_onset;
    auto r = at(h, 1, 0.0, gt);
    const double expected = std::min(1e9 * gt, limit);
    EXPECT_NEAR(r.shear[0], expected, 1e-9 * limit) << "step " << step;
    // On the yield surface itself (step 20) the point counts as sticking.
    EXPECT_EQ(r.state, 1e9 * gt <= 1.000001 * limit ? ContactState::stick : ContactState::slip);
    h = r.updated; // converged: commit
    tau_max = r.shear[0];
  }
  EXPECT_NEAR(tau_max, limit, 1e-9 * limit);
  // Reversal: unloads elastically at K_T from the slipped state.
  const double back = 0.3 * slip_onset;
  auto r = at(h, 1, 0.0, gt - back);
  EXPECT_EQ(r.state, ContactState::stick);
  EXPECT_NEAR(r.shear[0], limit - 1e9 * back, 1e-9 * limit);
  // Far enough back it slips the other way at -mu p'_N.
  r = at(h, 1, 0.0, gt - 3.0 * slip_onset);
  EXPECT_EQ(r.state, ContactState::slip);
  EXPECT_NEAR(r.shear[0], -limit, 1e-9 * limit);
}

TEST(Contact, ObliqueSlidingIsParallelToTheSlipIncrement)
{
  ContactHistory h;
  const double dir[2] = {std::cos(0.7), std::sin(0.7)};
  auto r = at(h, 2, -2e-6, 1e-3 * dir[0], 1e-3 * dir[1]);
  EXPECT_EQ(r.state, ContactState::slip);
  const double pn = r.contact_pressure_effective;
  EXPECT_NEAR(pn, 1.2e5, 1e-6);
  EXPECT_NEAR(std::hypot(r.shear[0], r.shear[1]), 0.57 * pn, 1e-9 * pn);
  EXPECT_NEAR(r.shear[0] * dir[1] - r.shear[1] * dir[0], 0.0, 1e-9 * pn);
  EXPECT_GT(r.shear[0] * dir[0] + r.shear[1] * dir[1], 0.0);
}

// Finite-difference check of the tangent in the stick, slip (2D and 3D) and open states,
// from a history with stress already in the interface.
struct TangentCase {
  const char *name;
  int nt;
  double gn, gt0, gt1;
  ContactState state;
};

class ContactTangent : public ::testing::TestWithParam<TangentCase> {};

TEST_P(ContactTangent, MatchesCentralDifferences)
{
  const auto c = GetParam();
  ContactHistory h;
  h.gap_tangential[0] = 1e-5;
  h.gap_tangential[1] = -2e-5;
  h.shear[0] = 2e4;
  h.shear[1] = -1e4;
  auto r = at(h, c.nt, c.gn, c.gt0, c.gt1);
  ASSERT_EQ(r.state, c.state);
  double g[3] = {c.gn, c.gt0, c.gt1};
  const double eps = 1e-10;
  double scale = 0.0;
  for (int i = 0; i <= c.nt; ++i)
    for (int j = 0; j <= c.nt; ++j)
      scale = std::max(scale, std::fabs(r.tangent[i][j]));
  for (int j = 0; j <= c.nt; ++j) {
    double gp[3] = {g[0], g[1], g[2]}, gm[3] = {g[0], g[1], g[2]};
    gp[j] += eps;
    gm[j] -= eps;
    auto rp = at(h, c.nt, gp[0], gp[1], gp[2]);
    auto rm = at(h, c.nt, gm[0], gm[1], gm[2]);
    const double vp[3] = {rp.contact_pressure_effective, rp.shear[0], rp.shear[1]};
    const double vm[3] = {rm.contact_pressure_effective, rm.shear[0], rm.shear[1]};
    for (int i = 0; i <= c.nt; ++i)
      EXPECT_NEAR((vp[i] - vm[i]) / (2 * eps), r.tangent[i][j], 1e-6 * std::max(scale, 1.0))
          << c.name << " d" << i << "/d" << j;
  }
}

INSTANTIATE_TEST_SUITE_P(
    States, ContactTangent,
    ::testing::Values(TangentCase{"stick2d", 1, -1e-6, 2e-5, 0.0, ContactState::stick},
                      TangentCase{"slip2d", 1, -1e-6, 3e-4, 0.0, ContactState::slip},
                      TangentCase{"stick3d", 2, -1e-6, 1.5e-5, -2.5e-5, ContactState::stick},
                      TangentCase{"slip3d", 2, -3e-6, 2e-4, 4e-4, ContactState::slip},
                      TangentCase{"open3d", 2, 5e-5, 2e-4, 4e-4, ContactState::open}),
    [](const auto &info) { return std::string(info.param.name); });

// contactStateChanges: along g + s dg the branch (open / stick / slip) changes only at the
// reported s, and at each reported s it does change (sampled on a fine grid), in 2D and 3D,
// from stick, slip and open starts, with a history that has slipped.
TEST(Contact, StateChangesAlongAStepAreTheKinks)
{
  ContactHistory h;
  h.gap_tangential[0] = 2e-6, h.gap_tangential[1] = -1e-6;
  h.shear[0] = 3e4, h.shear[1] = -2e4; // |tau_n| = 3.6e4 < mu p'_N0 = 5.7e4
  unsigned seed = 12345;
  auto uniform = [&seed](double a, double b) {
    seed = seed * 1103515245u + 12345u;
    return a + (b - a) * ((seed >> 8) & 0xffff) / 65535.0;
  };
  int changes_seen = 0;
  for (int nt = 1; nt <= 2; ++nt)
    for (int trial = 0; trial < 200; ++trial) {
      const double gn = uniform(-2e-5, 2e-5), dgn = uniform(-4e-5, 4e-5);
      const double gt[2] = {uniform(-1e-4, 1e-4), nt == 2 ? uniform(-1e-4, 1e-4) : 0.0};
      const double dgt[2] = {uniform(-2e-4, 2e-4), nt == 2 ? uniform(-2e-4, 2e-4) : 0.0};
      std::vector<double> kinks;
      contactStateChanges(kParams, kInitial, h, nt, gn, gt, dgn, dgt, kinks);
      auto state = [&](double s) {
        const double g[2] = {gt[0] + s * dgt[0], gt[1] + s * dgt[1]};
        return contactResponse(kParams, kInitial, h, nt, gn + s * dgn, g).state;
      };
      const int n = 4000;
      for (int i = 0; i < n; ++i) {
        const double a = double(i) / n, b = double(i + 1) / n;
        bool reported = false;
        for (double s : kinks)
          reported = reported || (s > a - 1e-9 && s <= b + 1e-9);
        if (state(a) != state(b)) {
          ++changes_seen;
          EXPECT_TRUE(reported) << "nt " << nt << " trial " << trial << ": change in [" << a
                                << ", " << b << "] not reported";
        }
      }
      for (double s : kinks) {
        EXPECT_GT(s, 0.0);
        EXPECT_LE(s, 1.0);
        const double lo = std::max(0.0, s - 1e-6), hi = std::min(1.0, s + 1e-6);
        EXPECT_NE(state(lo), state(hi)) << "nt " << nt << " trial " << trial << ": s = " << s;
      }
    }
  EXPECT_GT(changes_seen, 100);
}
