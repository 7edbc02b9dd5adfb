// The exact solutions of the interface patch test with quadratic jumps
// (test_quad_patch_jump.cpp): a block on a base, interface x_n = 0.5, two elastic bodies whose
// displacements are polynomials of degree 2, built from their traces and the interface traction
// and checked independently (constructionDefect).
//
// Which quadratic jumps an exact solution can have. A quadratic displacement has a linear
// stress, so the traction sigma n on the interface is linear along it, and it is the same from
// both sides. The interface law then fixes what the jump [u] = u_block - u_base may be:
//   stick: t = K [u] (K_N normal, K_T tangential): the jump is linear along the interface (a
//          quadratic jump would need a quadratic traction, i.e. cubic displacements). Each body
//          still has a quadratic field with a quadratic trace on the interface, and the traction
//          varies along it;
//   slip:  t_N = -p_N = K_N g_N (the closure is linear) and t_T = mu p_N e along a fixed slip
//          direction e: the slip g_T = s e may be any quadratic s with K_T s > mu p_N (the trial
//          traction past the Coulomb limit): a quadratic slip under a linearly varying contact
//          pressure and friction;
//   open:  t = 0: the opening and the tangential jump are any quadratics with g_N > 0.
// So the quadratic slip is tested in slip and the quadratic opening with the open interface;
// stick has quadratic bodies and a linear jump. A quadratic opening and slip in stick needs a
// load on the interface, which the cases "_loaded" manufacture: the jump gets a quadratic part
// q and the faces a load pair s = K q (-s on side 1, +s on side 2), integrated by the test
// with each face's own basis and a degree-4 rule, not through the interface assembly. Those
// cases use the Gauss rule: Simpson's (nodal) rule is not exact for the quadratic K [u] times
// a quadratic test function (measured: gaps off by 5e-4 relative), a quadrature error rather
// than a fault; with the physical traction (linear) above it is exact.
//
// Construction of a body's field from its trace w(xi) (quadratic in the tangential coordinates
// xi) and the interface traction t(xi) (linear): u = w(xi) + zeta A(xi) + zeta^2 c, zeta the
// normal coordinate (0 on the interface). sigma n = t at zeta = 0 gives A (linear):
//   tangential i: G (A_i + d_i w_n) = t_i;   normal: lambda (sum_t d_t w_t + A_n) + 2 G A_n = t_n,
// and equilibrium without body force, (lambda + G) grad div u + G lap u = 0 (a constant),
// gives c. The test checks the result independently: div sigma by central differences of the
// (linear) stress, and sigma n of both bodies against t at points of the interface.
#pragma once

#include "poroseam/contact.hpp"

#include <algorithm>
#include <cmath>

namespace poroseam::test_support {

constexpr double kNormalStiffness = 2e9, kTangentialStiffness = 1e9, kFriction = 0.5; // Pa/m, -
constexpr double kCentre = 0.5; ///< the interface plane and the middle of its square / segment

/// The interface's regime, as physics::ContactState numbers it.
enum class Regime {
  open = (int)physics::ContactState::open,
  stick = (int)physics::ContactState::stick,
  slip = (int)physics::ContactState::slip
};

struct Material {
  double young, poisson;
  double lambda() const { return young * poisson / ((1 + poisson) * (1 - 2 * poisson)); }
  double shear() const { return young / (2 * (1 + poisson)); }
};
const Material kBase{1e8, 0.25}, kBlock{5e7, 0.35};

/// v_i(xi) = v0_i + v1_it xi_t + 1/2 v2_its xi_t xi_s over the tangential axes t, s < n.
struct Quadratic {
  double v0[3] = {0, 0, 0}, v1[3][3] = {{0}}, v2[3][3][3] = {{{0}}};
  double value(int dim, int i, const double xi[3]) const
  {
    double v = v0[i];
    for (int t = 0; t < dim - 1; ++t) {
      v += v1[i][t] * xi[t];
      for (int s = 0; s < dim - 1; ++s)
        v += 0.5 * v2[i][t][s] * xi[t] * xi[s];
    }
    return v;
  }
};

/// One body's exact displacement u(y) = w(xi) + zeta A(xi) + zeta^2 c, y = x - centre,
/// xi = tangential components of y, zeta = y_n.
struct BodyField {
  int dim = 2;
  Quadratic w;
  double A0[3] = {0, 0, 0}, A1[3][3] = {{0}}, c[3] = {0, 0, 0};
  Material m;

  void value(const double x[3], double u[3]) const
  {
    double y[3] = {0, 0, 0};
    for (int d = 0; d < dim; ++d)
      y[d] = x[d] - kCentre;
    const double zeta = y[dim - 1];
    for (int i = 0; i < dim; ++i) {
      double a = A0[i];
      for (int t = 0; t < dim - 1; ++t)
        a += A1[i][t] * y[t];
      u[i] = w.value(dim, i, y) + zeta * a + zeta * zeta * c[i];
    }
  }
  void gradient(const double x[3], double g[3][3]) const
  {
    double y[3] = {0, 0, 0};
    for (int d = 0; d < dim; ++d)
      y[d] = x[d] - kCentre;
    const int n = dim - 1;
    const double zeta = y[n];
    for (int i = 0; i < dim; ++i) {
      for (int t = 0; t < n; ++t) {
        g[i][t] = w.v1[i][t] + zeta * A1[i][t];
        for (int s = 0; s < n; ++s)
          g[i][t] += w.v2[i][t][s] * y[s];
      }
      g[i][n] = A0[i] + 2.0 * zeta * c[i];
      for (int t = 0; t < n; ++t)
        g[i][n] += A1[i][t] * y[t];
    }
  }
  void stress(const double x[3], double sigma[3][3]) const
  {
    double g[3][3];
    gradient(x, g);
    double div = 0.0;
    for (int i = 0; i < dim; ++i)
      div += g[i][i];
    for (int i = 0; i < dim; ++i)
      for (int j = 0; j < dim; ++j)
        sigma[i][j] = m.shear() * (g[i][j] + g[j][i]) + (i == j ? m.lambda() * div : 0.0);
  }
};

/// The field of a body of material m with trace w on the interface and traction t = sigma n
/// there (t linear: t.v2 = 0); see the header.
inline BodyField buildBody(int dim, const Material &m, const Quadratic &w, const Quadratic &t)
{
  BodyField b;
  b.dim = dim;
  b.m = m;
  b.w = w;
  const int n = dim - 1;
  const double lambda = m.lambda(), G = m.shear();
  double div_w0 = 0.0, div_w1[3] = {0, 0, 0}; // sum_t d_t w_t: its value at xi = 0 and slope
  for (int t = 0; t < n; ++t) {
    div_w0 += w.v1[t][t];
    for (int s = 0; s < n; ++s)
      div_w1[s] += w.v2[t][t][s];
  }
  for (int i = 0; i < n; ++i) {
    b.A0[i] = t.v0[i] / G - w.v1[n][i];
    for (int s = 0; s < n; ++s)
      b.A1[i][s] = t.v1[i][s] / G - w.v2[n][i][s];
  }
  b.A0[n] = (t.v0[n] - lambda * div_w0) / (lambda + 2 * G);
  for (int s = 0; s < n; ++s)
    b.A1[n][s] = (t.v1[n][s] - lambda * div_w1[s]) / (lambda + 2 * G);
  // (lambda + G) d_i div u + G lap u_i = 0, lap u_i = sum_t d_tt w_i + 2 c_i.
  double dA = 0.0, lap_wn = 0.0;
  for (int t = 0; t < n; ++t) {
    dA += b.A1[t][t];
    lap_wn += w.v2[n][t][t];
  }
  for (int i = 0; i < n; ++i) {
    double lap_wi = 0.0;
    for (int t = 0; t < n; ++t)
      lap_wi += w.v2[i][t][t];
    b.c[i] = -((lambda + G) * (div_w1[i] + b.A1[n][i]) + G * lap_wi) / (2 * G);
  }
  b.c[n] = -((lambda + G) * dA + G * lap_wn) / (2 * lambda + 4 * G);
  return b;
}

/// Fixed "arbitrary" numbers in [-1, 1] for coefficients.
inline double coefficient(int i, int j, int k)
{
  return std::sin(1.0 + i + 3.1 * j + 7.3 * k);
}

/// The exact solution of a regime: both bodies, the interface traction and the jump.
struct Exact {
  int dim = 2;
  Regime regime = Regime::stick;
  Quadratic traction, jump;
  BodyField base, block;
  double slip_direction[3] = {0, 0, 0}; ///< e (slip): global, tangential
  /// Stick with a manufactured interface load: s = K [u] - sigma n [Pa], global components,
  /// applied as a line (surface) load pair, -s on side 1 and +s on side 2. Zero otherwise.
  bool loaded = false;
  Quadratic interface_load;
};

inline Exact exactSolution(int dim, Regime regime, bool loaded = false)
{
  Exact e;
  e.dim = dim;
  e.regime = regime;
  e.loaded = loaded;
  const int n = dim - 1;
  // The base's trace: a general quadratic (every component, every monomial), about 1 mm.
  Quadratic w_base;
  for (int i = 0; i < dim; ++i) {
    w_base.v0[i] = 1e-3 * coefficient(i, 0, 0);
    for (int t = 0; t < n; ++t) {
      w_base.v1[i][t] = 1e-3 * coefficient(i, t + 1, 0);
      for (int s = 0; s <= t; ++s)
        w_base.v2[i][t][s] = w_base.v2[i][s][t] = 2e-3 * coefficient(i, t + 1, s + 1);
    }
  }
  // Contact pressure p_N = 1e5 Pa (1 + 0.3 xi_0 + 0.2 xi_1) > 0 on |xi| <= 0.5.
  Quadratic normal; // sigma_nn
  normal.v0[n] = -1e5;
  normal.v1[n][0] = -0.3e5;
  if (dim == 3) normal.v1[n][1] = -0.2e5;
  Quadratic &t = e.traction, &g = e.jump;
  switch (regime) {
  case Regime::stick:
    // Shear within the friction limit everywhere: |tau| <= 3.1e4 < mu p_N >= 3.75e4 Pa; the
    // jump t / K is linear.
    t = normal;
    t.v0[0] = 2e4, t.v1[0][0] = -0.8e4;
    if (dim == 3) t.v1[0][1] = 0.6e4, t.v0[1] = -1e4, t.v1[1][0] = -0.5e4, t.v1[1][1] = 0.2e4;
    for (int i = 0; i < dim; ++i) {
      const double K = i == n ? kNormalStiffness : kTangentialStiffness;
      g.v0[i] = t.v0[i] / K;
      for (int s = 0; s < n; ++s)
        g.v1[i][s] = t.v1[i][s] / K;
    }
    if (loaded) {
      // A quadratic part q of the jump on top, held by the load s = K q (the traction K [u]
      // of the law minus the bodies' sigma n): contact pressure >= 0.75e5 - 1.5e4 Pa, shear
      // |tau + K_T q_T| <= 1.55e4 + 5e3 < mu p_N: stick everywhere.
      for (int k = 0; k < n; ++k) {
        t.v0[k] *= 0.5;
        for (int r = 0; r < n; ++r)
          t.v1[k][r] *= 0.5;
      }
      for (int i = 0; i < dim; ++i) {
        const double K = i == n ? kNormalStiffness : kTangentialStiffness;
        g.v0[i] = t.v0[i] / K;
        for (int s = 0; s < n; ++s)
          g.v1[i][s] = t.v1[i][s] / K;
        // |K q_i| <= 0.9 x 1.5e4 (normal), 5e3 Pa (tangential) on |xi| <= 0.5.
        const double amp = (i == n ? 1.5e4 : 5e3) / K;
        for (int s = 0; s < n; ++s)
          for (int r = 0; r < n; ++r)
            g.v2[i][s][r] = amp * (r == s ? (s == 0 ? 6.0 : -4.0) : 2.0) / (n == 2 ? 2.0 : 1.0);
        for (int s = 0; s < n; ++s)
          for (int r = 0; r < n; ++r)
            e.interface_load.v2[i][s][r] = K * g.v2[i][s][r];
      }
    }
    break;
  case Regime::slip: {
    // tau = mu p_N e, the slip s e quadratic with K_T s >= 1.3e5 Pa > mu p_N <= 6.25e4 Pa.
    const double angle = dim == 3 ? M_PI / 6 : 0.0;
    e.slip_direction[0] = std::cos(angle);
    if (dim == 3) e.slip_direction[1] = std::sin(angle);
    t = normal;
    g.v0[n] = normal.v0[n] / kNormalStiffness;
    for (int s = 0; s < n; ++s)
      g.v1[n][s] = normal.v1[n][s] / kNormalStiffness;
    Quadratic slip; // s(xi) in component 0
    slip.v0[0] = 2e-4;
    slip.v1[0][0] = 0.8e-4, slip.v2[0][0][0] = 3.2e-4;
    if (dim == 3)
      slip.v1[0][1] = -0.6e-4, slip.v2[0][1][1] = 2.4e-4, slip.v2[0][0][1] = -1e-4,
      slip.v2[0][1][0] = -1e-4;
    for (int k = 0; k < n; ++k) {
      const double ek = e.slip_direction[k];
      t.v0[k] = -kFriction * normal.v0[n] * ek;
      g.v0[k] = slip.v0[0] * ek;
      for (int s = 0; s < n; ++s) {
        t.v1[k][s] = -kFriction * normal.v1[n][s] * ek;
        g.v1[k][s] = slip.v1[0][s] * ek;
        for (int r = 0; r < n; ++r)
          g.v2[k][s][r] = slip.v2[0][s][r] * ek;
      }
    }
    break;
  }
  case Regime::open:
    // No traction; opening 1e-4 m (1 + 0.3 xi_0 + 1.6 xi_0^2 ...) > 0, any tangential jump.
    for (int i = 0; i < dim; ++i) {
      g.v0[i] = i == n ? 1e-4 : 5e-5 * coefficient(i, 5, 0);
      for (int s = 0; s < n; ++s) {
        g.v1[i][s] = i == n ? 0.3e-4 * (s + 1) : 5e-5 * coefficient(i, 5, s + 1);
        for (int r = 0; r <= s; ++r)
          g.v2[i][s][r] = g.v2[i][r][s] =
              i == n ? (r == s ? 3.2e-4 : -0.4e-4) : 1e-4 * coefficient(i, s + 6, r);
      }
    }
    break;
  }
  Quadratic w_block = w_base;
  for (int i = 0; i < dim; ++i) {
    w_block.v0[i] += g.v0[i];
    for (int s = 0; s < n; ++s) {
      w_block.v1[i][s] += g.v1[i][s];
      for (int r = 0; r < n; ++r)
        w_block.v2[i][s][r] += g.v2[i][s][r];
    }
  }
  e.base = buildBody(dim, kBase, w_base, t);
  e.block = buildBody(dim, kBlock, w_block, t);
  return e;
}

/// Independent check of the construction: div sigma = 0 in both bodies (central differences of
/// the linear stress: exact up to round-off), sigma n = t from both sides on the interface,
/// and in stick K [u] = t + s (s the manufactured load, if any).
/// Returns the largest violation relative to the stress scale (1e5 Pa).
inline double constructionDefect(const Exact &e)
{
  const int dim = e.dim, n = dim - 1;
  double worst = 0.0;
  const double h = 0.1, scale = 1e5;
  for (const BodyField *b : {&e.base, &e.block})
    for (double a : {0.1, 0.7})
      for (double z : {0.2, 0.8}) {
        double x[3] = {a, dim == 3 ? 1.0 - a : z, z};
        for (int i = 0; i < dim; ++i) {
          double div = 0.0;
          for (int j = 0; j < dim; ++j) {
            double xp[3] = {x[0], x[1], x[2]}, xm[3] = {x[0], x[1], x[2]};
            xp[j] += h, xm[j] -= h;
            double sp[3][3], sm[3][3];
            b->stress(xp, sp);
            b->stress(xm, sm);
            div += (sp[i][j] - sm[i][j]) / (2 * h);
          }
          worst = std::max(worst, std::fabs(div) / scale);
        }
      }
  for (double a : {0.0, 0.3, 1.0})
    for (double c : {0.0, 0.6, 1.0}) {
      double x[3] = {a, c, c};
      x[n] = kCentre;
      double xi[3] = {a - kCentre, c - kCentre, 0};
      for (const BodyField *b : {&e.base, &e.block}) {
        double s[3][3];
        b->stress(x, s);
        for (int i = 0; i < dim; ++i)
          worst = std::max(worst, std::fabs(s[i][n] - e.traction.value(dim, i, xi)) / scale);
      }
      // Stick: the law's traction K [u] is sigma n plus the load (zero unless loaded).
      if (e.regime != Regime::stick) continue;
      for (int i = 0; i < dim; ++i) {
        const double K = i == n ? kNormalStiffness : kTangentialStiffness;
        worst =
            std::max(worst, std::fabs(K * e.jump.value(dim, i, xi) - e.traction.value(dim, i, xi) -
                                      e.interface_load.value(dim, i, xi)) /
                                scale);
      }
    }
  return worst;
}
} // namespace poroseam::test_support
