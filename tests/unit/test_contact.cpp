// Interface contact and Coulomb friction: closed-form paths (shear ramp, reversal, opening,
// oblique sliding) and the consistent tangent against finite differences in every state.
#include "poroseam/contact.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>

using namespace poroseam::physics;

namespace {
const ContactParameters kParams{1e10, 1e9, 0.57};
const ContactInitial kInitial{0.0, 1e5}; // in contact at 100 kPa

ContactResponse at(const ContactHistory &h, int nt, double gn, double gt0, double gt1 = 0.0)
{
  const double gt[2] = {gt0, gt1};
  return contactResponse(kParams, kInitial, h, nt, gn, gt);
}

struct SweepCounts {
  int changes = 0;         ///< branch changes seen on the grids
  int low_bit_changes = 0; ///< ... of which only bit 0 of the branch number flipped
};

/// contactStateChanges against the sampled branch: 200 random steps g + s dg in 2D and 200 in
/// 3D from the history h (a fixed pseudo-random sequence from seed); on a grid of 4000 points
/// in s every change of branch(response) lies at a reported s, and at each reported s the
/// branch changes. branch maps a response to an integer (its state, or more).
template <class Branch>
SweepCounts checkStateChangesAgainstSampling(const ContactParameters &p, const ContactHistory &h,
                                             unsigned seed, Branch branch)
{
  auto uniform = [&seed](double a, double b) {
    seed = seed * 1103515245u + 12345u;
    return a + (b - a) * ((seed >> 8) & 0xffff) / 65535.0;
  };
  SweepCounts counts;
  for (int nt = 1; nt <= 2; ++nt)
    for (int trial = 0; trial < 200; ++trial) {
      const double gn = uniform(-2e-5, 2e-5), dgn = uniform(-4e-5, 4e-5);
      const double gt[2] = {uniform(-1e-4, 1e-4), nt == 2 ? uniform(-1e-4, 1e-4) : 0.0};
      const double dgt[2] = {uniform(-2e-4, 2e-4), nt == 2 ? uniform(-2e-4, 2e-4) : 0.0};
      std::vector<double> kinks;
      contactStateChanges(p, kInitial, h, nt, gn, gt, dgn, dgt, kinks);
      auto along = [&](double s) {
        const double g[2] = {gt[0] + s * dgt[0], gt[1] + s * dgt[1]};
        return branch(contactResponse(p, kInitial, h, nt, gn + s * dgn, g));
      };
      const int n = 4000;
      for (int i = 0; i < n; ++i) {
        const double a = double(i) / n, b = double(i + 1) / n;
        bool reported = false;
        for (double s : kinks)
          reported = reported || (s > a - 1e-9 && s <= b + 1e-9);
        const int ba = along(a), bb = along(b);
        if (ba != bb) {
          ++counts.changes;
          if ((ba ^ bb) == 1) ++counts.low_bit_changes;
          EXPECT_TRUE(reported) << "nt " << nt << " trial " << trial << ": change in [" << a << ", "
                                << b << "] not reported";
        }
      }
      for (double s : kinks) {
        EXPECT_GT(s, 0.0);
        EXPECT_LE(s, 1.0);
        const double lo = std::max(0.0, s - 1e-6), hi = std::min(1.0, s + 1e-6);
        EXPECT_NE(along(lo), along(hi)) << "nt " << nt << " trial " << trial << ": s = " << s;
      }
    }
  return counts;
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
  const SweepCounts counts = checkStateChangesAgainstSampling(
      kParams, h, 12345u, [](const ContactResponse &r) { return (int)r.state; });
  EXPECT_GT(counts.changes, 100);
}

// ---------------------------------------------------------------------------------------------
// Shear dilation: the normal gap grows by tan(psi) per unit plastic slip, up to a slip limit.
namespace {
const double kTanPsi = std::tan(10.0 * M_PI / 180.0);

ContactParameters dilatant(double slip_limit = std::numeric_limits<double>::infinity())
{
  ContactParameters p = kParams;
  p.dilation = kTanPsi;
  p.dilation_slip_limit = slip_limit;
  return p;
}
} // namespace

// A joint held at a fixed normal gap (infinite normal stiffness of the surroundings: only the
// penalty K_N) and sheared monotonically: in slip p'_N = p'_N0 + K_N tan(psi) s_p with
// s_p = g_T - tau / K_T, tau = mu p'_N, so
//   p'_N = (p'_N0 + K_N tan(psi) g_T) / (1 + mu K_N tan(psi) / K_T),
// whatever the steps (the plastic slip of a step closes the return exactly); beyond the slip
// limit the pressure stays at p'_N0 + K_N tan(psi) s_lim.
TEST(ContactDilation, ConstantNormalGapShearRamp)
{
  const double limit_slip = 2e-4;
  const ContactParameters p = dilatant(limit_slip);
  const double kn = p.normal_stiffness, kt = p.tangential_stiffness, mu = p.friction;
  for (int steps : {1, 7, 400}) {
    ContactHistory h;
    const double gt_end = 1e-4;
    ContactResponse r;
    for (int i = 1; i <= steps; ++i) {
      const double gt[2] = {gt_end * i / steps, 0.0};
      r = contactResponse(p, kInitial, h, 1, 0.0, gt);
      h = r.updated;
    }
    const double expected = (1e5 + kn * kTanPsi * gt_end) / (1.0 + mu * kn * kTanPsi / kt);
    EXPECT_EQ(r.state, ContactState::slip);
    EXPECT_NEAR(r.contact_pressure_effective, expected, 1e-10 * expected) << steps << " steps";
    EXPECT_NEAR(r.shear[0], mu * expected, 1e-10 * expected);
    EXPECT_NEAR(h.slip_plastic, gt_end - mu * expected / kt, 1e-12 * gt_end);
    EXPECT_NEAR(r.dilation, kTanPsi * h.slip_plastic, 1e-20);
  }
  // Past the limit (in one step from a history below it, and in many).
  for (int steps : {1, 50}) {
    ContactHistory h;
    ContactResponse r;
    for (int i = 1; i <= steps; ++i) {
      const double gt[2] = {5e-4 * i / steps, 0.0};
      r = contactResponse(p, kInitial, h, 1, 0.0, gt);
      h = r.updated;
    }
    const double expected = 1e5 + kn * kTanPsi * limit_slip;
    EXPECT_NEAR(r.contact_pressure_effective, expected, 1e-10 * expected) << steps << " steps";
    EXPECT_NEAR(r.dilation, kTanPsi * limit_slip, 1e-20);
    EXPECT_NEAR(h.slip_plastic, 5e-4 - mu * expected / kt, 1e-12);
    EXPECT_EQ(r.d_dilation[0], 0.0);
    EXPECT_EQ(r.d_dilation[1], 0.0);
  }
}

// Zero angle: the law of the undilatant interface, value for value, while the plastic slip is
// still accumulated.
TEST(ContactDilation, ZeroAngleIsTheCoulombLaw)
{
  ContactParameters p = kParams;
  p.dilation_slip_limit = 1e-6; // ignored without an angle
  ContactHistory h0, h1;
  for (int i = 1; i <= 30; ++i) {
    const double gt[2] = {3e-6 * i * std::cos(0.1 * i), 2e-6 * i * std::sin(0.2 * i)};
    const double gn = -1e-6 * std::sin(0.3 * i);
    auto a = contactResponse(kParams, kInitial, h0, 2, gn, gt);
    auto b = contactResponse(p, kInitial, h1, 2, gn, gt);
    EXPECT_EQ(a.state, b.state);
    EXPECT_EQ(a.contact_pressure_effective, b.contact_pressure_effective);
    for (int k = 0; k < 2; ++k)
      EXPECT_EQ(a.shear[k], b.shear[k]);
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l)
        EXPECT_EQ(a.tangent[k][l], b.tangent[k][l]);
    EXPECT_EQ(b.dilation, 0.0);
    h0 = a.updated, h1 = b.updated;
  }
  EXPECT_GT(h1.slip_plastic, 0.0);
}

// A joint that has slid keeps its dilation when it opens and closes again: the contact
// position is g_N,0 + p'_N0 / K_N + d, and the mechanical opening is measured from it.
TEST(ContactDilation, DilationSurvivesOpeningAndMovesTheContactPosition)
{
  const ContactParameters p = dilatant();
  ContactHistory h;
  h.slip_plastic = 5e-5; // d = 8.8 um
  const double d = kTanPsi * 5e-5;
  const double gt[2] = {0.0, 0.0};
  // Touching position 10 um + d: just below it in contact, just above open.
  auto r = contactResponse(p, kInitial, h, 1, 1e-5 + d - 1e-7, gt);
  EXPECT_EQ(r.state, ContactState::stick);
  EXPECT_NEAR(r.contact_pressure_effective, 1e10 * 1e-7, 1e-6);
  r = contactResponse(p, kInitial, h, 1, 1e-5 + d + 1e-7, gt);
  EXPECT_EQ(r.state, ContactState::open);
  EXPECT_EQ(r.updated.slip_plastic, 5e-5);
  EXPECT_NEAR(r.dilation, d, 1e-20);
  EXPECT_NEAR(mechanicalOpening(p, kInitial, 1e-5 + d + 1e-7, r.dilation), 1e-7, 1e-18);
}

// The tangent (and the derivative of the dilation) against central differences with dilation:
// stick from a dilated history, slip below the limit, a step that reaches the limit, slip
// past the limit, and open; 2D and 3D.
struct DilatantCase {
  const char *name;
  int nt;
  double gn, gt0, gt1;
  double slip_plastic; ///< of the history
  double slip_limit;
  ContactState state;
};

void PrintTo(const DilatantCase &c, std::ostream *os)
{
  *os << c.name;
}

class ContactDilationTangent : public ::testing::TestWithParam<DilatantCase> {};

TEST_P(ContactDilationTangent, MatchesCentralDifferences)
{
  const auto c = GetParam();
  const ContactParameters p = dilatant(c.slip_limit);
  ContactHistory h;
  h.gap_tangential[0] = 1e-5;
  h.gap_tangential[1] = -2e-5;
  h.shear[0] = 2e4;
  h.shear[1] = c.nt == 2 ? -1e4 : 0.0;
  h.slip_plastic = c.slip_plastic;
  auto eval = [&](const double g[3]) {
    const double gt[2] = {g[1], g[2]};
    return contactResponse(p, kInitial, h, c.nt, g[0], gt);
  };
  const double g[3] = {c.gn, c.gt0, c.gt1};
  const auto r = eval(g);
  ASSERT_EQ(r.state, c.state);
  if (c.state == ContactState::slip && c.slip_plastic < c.slip_limit)
    EXPECT_GT(r.dilation, kTanPsi * c.slip_plastic) << "the step dilates";
  const double eps = 1e-10;
  double scale = 0.0;
  for (int i = 0; i <= c.nt; ++i)
    for (int j = 0; j <= c.nt; ++j)
      scale = std::max(scale, std::fabs(r.tangent[i][j]));
  double dscale = 0.0;
  for (int j = 0; j <= c.nt; ++j)
    dscale = std::max(dscale, std::fabs(r.d_dilation[j]));
  for (int j = 0; j <= c.nt; ++j) {
    double gp[3] = {g[0], g[1], g[2]}, gm[3] = {g[0], g[1], g[2]};
    gp[j] += eps;
    gm[j] -= eps;
    const auto rp = eval(gp), rm = eval(gm);
    ASSERT_EQ(rp.state, c.state);
    ASSERT_EQ(rm.state, c.state);
    const double vp[3] = {rp.contact_pressure_effective, rp.shear[0], rp.shear[1]};
    const double vm[3] = {rm.contact_pressure_effective, rm.shear[0], rm.shear[1]};
    for (int i = 0; i <= c.nt; ++i)
      EXPECT_NEAR((vp[i] - vm[i]) / (2 * eps), r.tangent[i][j], 1e-6 * std::max(scale, 1.0))
          << c.name << " d" << i << "/d" << j;
    EXPECT_NEAR((rp.dilation - rm.dilation) / (2 * eps), r.d_dilation[j],
                1e-6 * std::max(dscale, 1e-3))
        << c.name << " d(dilation)/d" << j;
  }
}

INSTANTIATE_TEST_SUITE_P(
    States, ContactDilationTangent,
    ::testing::Values(
        DilatantCase{"stick2d", 1, -1e-6, 2e-5, 0.0, 3e-5, 1e-3, ContactState::stick},
        DilatantCase{"slip2d", 1, -1e-6, 3e-4, 0.0, 3e-5, 1e-3, ContactState::slip},
        DilatantCase{"slip2d_backwards", 1, -1e-6, -3e-4, 0.0, 3e-5, 1e-3, ContactState::slip},
        DilatantCase{"slip2d_unlimited", 1, -1e-6, 3e-4, 0.0, 3e-5,
                     std::numeric_limits<double>::infinity(), ContactState::slip},
        DilatantCase{"slip2d_reaches_limit", 1, -1e-6, 3e-4, 0.0, 3e-5, 1e-4, ContactState::slip},
        DilatantCase{"slip2d_past_limit", 1, -1e-6, 3e-4, 0.0, 2e-4, 1e-4, ContactState::slip},
        DilatantCase{"stick3d", 2, -1e-6, 1.5e-5, -2.5e-5, 3e-5, 1e-3, ContactState::stick},
        DilatantCase{"slip3d", 2, -3e-6, 2e-4, 4e-4, 3e-5, 1e-3, ContactState::slip},
        DilatantCase{"slip3d_reaches_limit", 2, -3e-6, 2e-4, 4e-4, 3e-5, 1e-4, ContactState::slip},
        DilatantCase{"slip3d_past_limit", 2, -3e-6, 2e-4, 4e-4, 2e-4, 1e-4, ContactState::slip},
        DilatantCase{"open3d", 2, 5e-5, 2e-4, 4e-4, 3e-5, 1e-3, ContactState::open}),
    [](const auto &info) { return std::string(info.param.name); });

// With dilation and a slip limit, contactStateChanges also reports where the sliding reaches
// the limit: the branch (open / stick / slip below / slip past the limit) changes only at the
// reported s, and at each reported s something changes.
TEST(ContactDilation, StateChangesIncludeTheDilationLimit)
{
  const double slip_limit = 4e-5;
  const ContactParameters p = dilatant(slip_limit);
  ContactHistory h;
  h.gap_tangential[0] = 2e-6, h.gap_tangential[1] = -1e-6;
  h.shear[0] = 3e4, h.shear[1] = -2e4;
  h.slip_plastic = 2e-5; // d = 3.5 um, 2e-5 m of slip left to dilate
  // branch: the state, and in bit 0 whether the sliding is past the limit
  const SweepCounts counts =
      checkStateChangesAgainstSampling(p, h, 4321u, [slip_limit](const ContactResponse &r) {
        return 2 * (int)r.state + (r.updated.slip_plastic > slip_limit ? 1 : 0);
      });
  EXPECT_GT(counts.changes, 100);
  EXPECT_GT(counts.low_bit_changes, 20);
}
