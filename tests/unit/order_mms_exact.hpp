// The manufactured fields of the element-order tests (order_mms.hpp): sums of products of sines,
// their derivatives of any order in closed form, and the body force and fluid source that make them
// a solution of quasi-static Biot (plane strain, axisymmetric, 3D).
//
// With a cohesive interface at x = x0 (side 1 at x < x0, its normal e1 = +x), the fields of
// side 2 are those of side 1 plus a jump field built from side 1's state on the interface, so
// that the pair is an exact solution of the interface laws in their closed, sticking regime
// (docs/physics.md sections 4 and 5; src/assembly/interface_assembly.cpp):
//   mechanics: the total traction t = sigma'(u) e1 - alpha p e1 is continuous, and
//              t = K_N g_N e1 + K_T g_T - p3 e1 with the gap g = u2 - u1 (g_N < 0: compressed,
//              p'_N = -K_N g_N > 0; friction large enough never to slip);
//   flow:      f1 = T1 (p1 - p3) is side 1's Darcy outflow -kappa dp1/dx, f2 = T2 (p3 - p2) is
//              side 2's inflow -kappa dp2/dx, and the interface balance div_T q_l = f1 - f2 with
//              q_l = -C grad_T p3, C = D0^3 / (12 mu_w) (closed: aperture D0, no storage rate).
// Choosing p3 = p1 + (kappa / T1) dp1/dx fixes f1; f2 = f1 + C lap_T p3; then side 2's pressure
// is p1 + Q0(y) + sin(x - x0) Q1(y) with Q0 = p3 - f2 / T2 - p1 and Q1 = -(C / kappa) lap_T p3.
// The displacement jump J = g(y) + sin(x - x0) c(y) takes the gap g from the traction and the
// slope c that keeps the traction continuous with the pressure jump Q0:
//   c_0 = (alpha Q0 - lambda (sum_j dg_j/dx_j + g_0 / x0 [axisymmetric hoop])) / (lambda + 2G),
//   c_j = -dg_0/dx_j  (j tangential).
// Without flow (an impervious interface, no p3: mechanics only) both sides take the pressure
// P - sin(x - x0) dP/dx(x0), whose flux through the interface vanishes, the gap g_0 = t_0 / K_N,
// and no pressure jump (plane strain and 3D: that pressure is not regular on the axis).
// Side 1's u_x gets a compression -A sin(x) (odd in r: regular on the axis) so that the
// interface stays closed everywhere (p'_N from 2.3 to 3.7 at the integration points, printed).
#pragma once

#include <cmath>
#include <vector>

namespace poroseam::test_support {

/// amplitude prod_d sin(k_d x_d + f_d); a factor with k = 0 is the constant sin(f).
struct Product {
  double amplitude;
  double k[3], f[3];
  /// The derivative of orders n[d] along each axis: each order multiplies by k and shifts the
  /// phase by pi / 2.
  double derivative(int dim, const double *x, const int n[3]) const
  {
    double v = amplitude;
    for (int d = 0; d < dim; ++d)
      v *= (n[d] ? std::pow(k[d], n[d]) : 1.0) * std::sin(k[d] * x[d] + f[d] + n[d] * M_PI_2);
    return v;
  }
};

/// A sum of products.
struct Field {
  std::vector<Product> terms;
  Field() = default;
  Field(std::initializer_list<Product> p) : terms(p) {}
  double value(int dim, const double *x) const { return derivative(dim, x, -1, -1); }
  /// d^(n1 + n2) / dx_a dx_b with n derivatives: a, b < 0 means none.
  double derivative(int dim, const double *x, int a, int b) const
  {
    int n[3] = {0, 0, 0};
    if (a >= 0) ++n[a];
    if (b >= 0) ++n[b];
    double v = 0.0;
    for (const auto &t : terms)
      v += t.derivative(dim, x, n);
    return v;
  }
  /// d/dx_axis as a field.
  Field d(int axis) const
  {
    Field r = *this;
    for (auto &t : r.terms) {
      t.amplitude *= t.k[axis];
      t.f[axis] += M_PI_2;
    }
    return r;
  }
  /// The field on the plane x_axis = at, constant along axis.
  Field on(int axis, double at) const
  {
    Field r = *this;
    for (auto &t : r.terms) {
      t.amplitude *= std::sin(t.k[axis] * at + t.f[axis]);
      t.k[axis] = 0.0, t.f[axis] = M_PI_2;
    }
    return r;
  }
  /// A field constant along axis times sin(x_axis - at).
  Field times_sine(int axis, double at) const
  {
    Field r = *this;
    for (auto &t : r.terms)
      t.k[axis] = 1.0, t.f[axis] = -at;
    return r;
  }
  Field operator*(double s) const
  {
    Field r = *this;
    for (auto &t : r.terms)
      t.amplitude *= s;
    return r;
  }
  Field operator+(const Field &o) const
  {
    Field r = *this;
    r.terms.insert(r.terms.end(), o.terms.begin(), o.terms.end());
    return r;
  }
  Field operator-(const Field &o) const { return *this + o * -1.0; }
};

/// Material and interface constants of the manufactured problem.
struct MmsConstants {
  double young = 1.0, poisson = 0.3, storage = 0.5, mobility = 1.0; ///< kappa = k / mu_w
  double viscosity = 1e-3;                                          ///< mu_w (the scene's default)
  // The interface: penalties K h / E from 0.3 to 5 on these meshes; friction that never slips.
  double normal_stiffness = 10.0, tangential_stiffness = 5.0, friction = 1e3;
  double aperture0 = 0.1; ///< D0: C = D0^3 / (12 mu_w) = 0.083
  double transmissivity1 = 1.0, transmissivity2 = 0.5;
  double x0 = 0.5;          ///< the interface plane x = x0
  double compression = 2.0; ///< A of side 1's -A sin(x) along x
};

struct Exact {
  int dim;
  double alpha;      ///< Biot's coefficient: 0 decouples the displacement from the pressure
  bool axisymmetric; ///< x = r, y = z (dim 2)
  bool interface;    ///< side 2 (x > x0) differs by the jump fields
  bool flow;         ///< the interface has p3 and the three-node flow
  MmsConstants k;
  Field u[2][3], p[2]; ///< per side (side 1: index 0)
  Field p3;            ///< interface pressure (along the interface, constant in x)
  double lambda, G;
  Exact(int dim_, double alpha_, bool axisymmetric_ = false, bool interface_ = false,
        bool flow_ = false)
      : dim(dim_), alpha(alpha_), axisymmetric(axisymmetric_), interface(interface_), flow(flow_)
  {
    Product u0 = {0.1, {1.1 * M_PI, 0.7 * M_PI, 0.9 * M_PI}, {0.3, 0.5, 0.2}};
    Product u1 = {0.08, {0.6 * M_PI, 1.3 * M_PI, 0.8 * M_PI}, {0.7, 0.1, 0.4}};
    Product u2 = {0.06, {0.9 * M_PI, 0.8 * M_PI, 1.2 * M_PI}, {0.2, 0.6, 0.9}};
    Product pp = {0.1, {0.8 * M_PI, 1.2 * M_PI, 0.7 * M_PI}, {0.4, 0.2, 0.6}};
    if (axisymmetric) {
      // Regular on the axis: u_r = 0 there (odd in r), u_z and p even in r.
      u0.f[0] = 0.0;
      u1.f[0] = 0.5 * M_PI;
      pp.f[0] = 0.5 * M_PI;
    }
    u[0][0] = {u0}, u[0][1] = {u1}, u[0][2] = {u2}, p[0] = {pp};
    G = k.young / (2 * (1 + k.poisson));
    lambda = k.young * k.poisson / ((1 + k.poisson) * (1 - 2 * k.poisson));
    if (interface) {
      u[0][0] = u[0][0] + Field{Product{-k.compression, {1.0, 0.0, 0.0}, {0.0, M_PI_2, M_PI_2}}};
      buildSide2();
    } else {
      for (int i = 0; i < 3; ++i)
        u[1][i] = u[0][i];
      p[1] = p[0];
    }
  }

  /// Side 2's fields and p3 from side 1's state on x = x0 (see the file's comment).
  void buildSide2()
  {
    const double x0 = k.x0, M = lambda + 2 * G;
    const Field *U = u[0];
    if (!flow) p[0] = p[0] + (p[0].d(0).on(0, x0) * -1.0).times_sine(0, x0);
    const Field P = p[0];
    // Side 1's total traction on the plane, t = sigma e1.
    Field t[3];
    Field volumetric = U[0].d(0) * M;
    for (int j = 1; j < dim; ++j)
      volumetric = volumetric + U[j].d(j) * lambda;
    if (axisymmetric) volumetric = volumetric + U[0].on(0, x0) * (lambda / x0);
    t[0] = volumetric.on(0, x0) - P.on(0, x0) * alpha;
    for (int j = 1; j < dim; ++j)
      t[j] = (U[0].d(j) + U[j].d(0)).on(0, x0) * G;
    Field g[3], c[3], Q0;
    if (flow) {
      // Flow: p3, the transversal fluxes, and side 2's pressure.
      p3 = P.on(0, x0) + P.d(0).on(0, x0) * (k.mobility / k.transmissivity1);
      const Field f1 = P.d(0).on(0, x0) * -k.mobility;
      Field lap_p3;
      for (int j = 1; j < dim; ++j)
        lap_p3 = lap_p3 + p3.d(j).d(j);
      const double C = std::pow(k.aperture0, 3) / (12.0 * k.viscosity);
      const Field f2 = f1 + lap_p3 * C;
      Q0 = p3 - f2 * (1.0 / k.transmissivity2) - P.on(0, x0);
      const Field Q1 = lap_p3 * (-C / k.mobility);
      p[1] = P + Q0 + Q1.times_sine(0, x0);
    } else
      p[1] = P;
    // The gap, and the slope of the jump that keeps the traction continuous.
    g[0] = (t[0] + p3) * (1.0 / k.normal_stiffness);
    for (int j = 1; j < dim; ++j)
      g[j] = t[j] * (1.0 / k.tangential_stiffness);
    Field dilatation;
    for (int j = 1; j < dim; ++j)
      dilatation = dilatation + g[j].d(j);
    if (axisymmetric) dilatation = dilatation + g[0] * (1.0 / x0);
    c[0] = (Q0 * alpha - dilatation * lambda) * (1.0 / M);
    for (int j = 1; j < dim; ++j)
      c[j] = g[0].d(j) * -1.0;
    for (int i = 0; i < dim; ++i)
      u[1][i] = U[i] + g[i] + c[i].times_sine(0, x0);
  }

  /// The side of a point: 1 (index 1) beyond the interface.
  int sideOf(const double *x) const { return interface && x[0] > k.x0 ? 1 : 0; }
  /// u_r / r, the hoop strain (0 in plane strain).
  double hoop(int s, const double *x) const
  {
    return axisymmetric ? u[s][0].value(dim, x) / x[0] : 0.0;
  }
  double divU(int s, const double *x) const
  {
    double v = hoop(s, x);
    for (int i = 0; i < dim; ++i)
      v += u[s][i].derivative(dim, x, i, -1);
    return v;
  }
  /// lap f of a scalar (cylindrical when axisymmetric: + f_r / r).
  double laplacian(const Field &f, const double *x) const
  {
    double lap = axisymmetric ? f.derivative(dim, x, 0, -1) / x[0] : 0.0;
    for (int j = 0; j < dim; ++j)
      lap += f.derivative(dim, x, j, j);
    return lap;
  }
  /// f = -div(sigma'(u) - alpha p I) = -((lambda + G) grad div u + G lap u) + alpha grad p.
  void bodyForce(int s, const double *x, double f[3]) const
  {
    for (int i = 0; i < dim; ++i) {
      double grad_div = 0.0, lap = laplacian(u[s][i], x);
      for (int j = 0; j < dim; ++j)
        grad_div += u[s][j].derivative(dim, x, i, j);
      if (axisymmetric) {
        // d/dx_i (u_r / r); (lap u)_r - u_r / r^2.
        const double r = x[0], ur = u[s][0].value(dim, x);
        grad_div += i == 0 ? u[s][0].derivative(dim, x, 0, -1) / r - ur / (r * r)
                           : u[s][0].derivative(dim, x, i, -1) / r;
        if (i == 0) lap -= ur / (r * r);
      }
      f[i] = -((lambda + G) * grad_div + G * lap) + alpha * p[s].derivative(dim, x, i, -1);
    }
  }
  /// g = alpha div u_t + p_t / M - kappa lap p, with u_t = u and p_t = p.
  double source(int s, const double *x) const
  {
    return alpha * divU(s, x) + k.storage * p[s].value(dim, x) - k.mobility * laplacian(p[s], x);
  }
  /// Weight of a point's measure: 2 pi r when axisymmetric (the kernel's), else 1.
  double ring(const double *x) const { return axisymmetric ? 2.0 * M_PI * x[0] : 1.0; }
};

} // namespace poroseam::test_support
