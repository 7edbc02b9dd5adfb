// The bulk cell kernel: residual and Jacobian of quasi-static Biot consolidation (or
// elasticity) on one cell from its closure values, and the material data it needs. Used by
// Problem (problem.cpp); kept apart because it is the arithmetic core of the assembly.
#pragma once

#include "poroseam/biot.hpp"
#include "poroseam/elastic.hpp"
#include "poroseam/kernel_work.hpp"
#include "poroseam/reference_element.hpp"
#include "poroseam/scene.hpp"

#include "poroseam/skeleton_law.hpp"

#include <cmath>
#include <type_traits>
#include <vector>

namespace poroseam {

/// Everything the cell kernel needs about one cell's material.
struct CellMaterial {
  physics::ElasticModuli moduli;
  physics::BiotProperties biot;
  double density = 0.0; ///< rho_sat for porous regions, rho_s otherwise
  bool porous = false;  ///< region is porous
  double stabilization = 0.0;
  /// The skeleton law when it is not linear elastic (has history), else nullptr: the kernel
  /// then takes its linear path with `moduli`.
  const SkeletonLaw *law = nullptr;
};

/// Residual and (optionally) Jacobian of one bulk cell, from its closure values. Layout of
/// the closure (PETSc orders closures field by field): nn*dim displacements (nn nodes of the
/// element's node basis, closure order), then np pressures (np = nv vertices in porous
/// regions, linear basis). The kernel reads like the weak form:
///   R_u = int (sigma'_0 + C:eps(u) - alpha p I) : grad v - rho g . v
///   R_p = s int psi (alpha div u_t + p_t/M) - grad psi . q + beta grad psi . grad p_t
/// with q = -(k/mu_w)(grad p - rho_w g) and s the mass scale. With a skeleton law that has
/// history (m.law), sigma'_0 + C:eps is the law's sigma'(eps; committed history) and C its
/// consistent tangent, at every integration point.
struct CellKernel {
  const ReferenceElement &e;
  int dim;
  const CellMaterial &m;
  bool with_pressure; // the cell assembles the mass balance (porous and not drained)
  double mass_scale;
  double gravity[3];
  bool axisymmetric = false; // x = r, y = z: hoop strain u_r / r, weights 2 pi r
  /// With m.law: the committed history of the cell's integration points (one per point).
  const physics::SkeletonHistory *history = nullptr;
  /// With m.law and non-null: receives the law's response at every integration point (for
  /// committing the history and for outputs).
  physics::SkeletonResponse *responses = nullptr;
  /// Work arrays kept across cells (optional: without, the kernel allocates its own).
  CellKernelWork *work = nullptr;
  /// Curved cell (-mesh_geometry_order 2): coords are the nodes' places (nn x dim) and the
  /// node basis maps the cell (isoparametric); otherwise the vertices' (nv x dim).
  bool curved = false;

  template <class InitialStress, class InitialPressure>
  void operator()(const double *coords, const double *x, const double *xdot, int closure_size,
                  InitialStress &&stress0, InitialPressure &&pressure0, double *F, double shift,
                  double *J) const
  {
    // The space dimension as a compile-time constant: the loops over components unroll and
    // k / dim, k % dim become cheap (measured on the 3D caisson: the Jacobian kernel 259k -> 142k
    // instructions per hexahedron).
    // The law's path is a separate instantiation, so the linear one is the same code as
    // without laws.
    if (m.law) {
      if (dim == 3)
        evaluate<3, true>(coords, x, xdot, closure_size, stress0, pressure0, F, shift, J);
      else if (dim == 2)
        evaluate<2, true>(coords, x, xdot, closure_size, stress0, pressure0, F, shift, J);
      else
        evaluate<1, true>(coords, x, xdot, closure_size, stress0, pressure0, F, shift, J);
    } else if (dim == 3)
      evaluate<3, false>(coords, x, xdot, closure_size, stress0, pressure0, F, shift, J);
    else if (dim == 2)
      evaluate<2, false>(coords, x, xdot, closure_size, stress0, pressure0, F, shift, J);
    else
      evaluate<1, false>(coords, x, xdot, closure_size, stress0, pressure0, F, shift, J);
  }

  // noinline: inlined into Problem::cellTerms, the kernel took 10 % more instructions on the
  // 3D Terzaghi column (callgrind: 59.99M vs 54.42M for the same cells), register pressure in
  // one large function.
  template <int D, bool WithLaw, class InitialStress, class InitialPressure>
  __attribute__((noinline)) void evaluate(const double *coords, const double *x, const double *xdot,
                                          int closure_size, InitialStress &stress0,
                                          InitialPressure &pressure0, double *F, double shift,
                                          double *J) const
  {
    constexpr int dim = D; // hides the member: the same value, known to the compiler
    // nn displacement nodes (the closure's first nn * dim values), nv vertices: the pressure
    // (the next nv values) and the geometry.
    const int nv = e.num_vertices, nn = e.num_nodes, nu = nn * dim;
    CellKernelWork own;
    CellKernelWork &wk = work ? *work : own;
    wk.resize(nn, dim);
    // Strain variation of each displacement dof (a, i) and the stress it causes:
    // sym(e_i (x) grad N_a), plus the hoop strain N_a / r for radial dofs when
    // axisymmetric (tensor index 2 is then the hoop direction, out of plane otherwise).
    // __restrict: the work arrays share no memory with each other, the closure values or the
    // tables.
    CellKernelWork::Tensor *__restrict variation = wk.variation.data();
    CellKernelWork::Tensor *__restrict stress_of = wk.stress_of.data();
    double *__restrict div = wk.div.data();
    double *__restrict hoop = wk.hoop.data();
    // The law's response at the current point (a placeholder on the linear path).
    std::conditional_t<WithLaw, physics::SkeletonResponse, char> law_response;
    PointGeometry &g = wk.point;
    for (int q = 0; q < e.num_quadrature; ++q) {
      mapQuadraturePoint(e, coords, q, g, curved);
      const double *__restrict phi = g.phi; // vertex basis: pressure
      const double *__restrict dphi = g.grad_phi;
      const double *__restrict N = g.node_phi; // node basis: displacement
      const double *__restrict dN = g.grad_node_phi;
      const double r = g.x[0];
      const double w = axisymmetric ? g.weight * 2.0 * M_PI * r : g.weight;
      for (int a = 0; a < nn; ++a)
        for (int i = 0; i < dim; ++i) {
          double(&de)[3][3] = variation[a * dim + i].v;
          for (int m1 = 0; m1 < 3; ++m1)
            for (int m2 = 0; m2 < 3; ++m2)
              de[m1][m2] = 0.0;
          for (int j = 0; j < dim; ++j) {
            de[i][j] += 0.5 * dN[a * dim + j];
            de[j][i] += 0.5 * dN[a * dim + j];
          }
          if (axisymmetric && i == 0) de[2][2] = N[a] / r;
          if constexpr (!WithLaw) physics::elasticStress(m.moduli, de, stress_of[a * dim + i].v);
        }
      // Only row and column i of variation[a * dim + i] are non-zero (plus the hoop entry), so
      // for a symmetric s, s : variation = grad N_a . s e_i (+ s_hoop N_a / r): 3 products
      // instead of 9, the bulk of the Jacobian's arithmetic. div[k] = trace(variation[k]).
      // hoop[a] = N_a / r: hoop strain of a unit radial displacement, 0 if none.
      for (int a = 0; a < nn; ++a)
        hoop[a] = axisymmetric ? N[a] / r : 0.0;
      auto contract = [&](const double s[3][3], int k) {
        const int a = k / dim, i = k % dim;
        double v = 0.0;
        for (int j = 0; j < dim; ++j)
          v += s[i][j] * dN[a * dim + j];
        return i == 0 ? v + s[2][2] * hoop[a] : v;
      };
      for (int k = 0; k < nu; ++k)
        div[k] = dN[k] + (k % dim == 0 ? hoop[k / dim] : 0.0);
      double eps[3][3] = {{0}}, sigma[3][3];
      for (int k = 0; k < nu; ++k)
        for (int m1 = 0; m1 < 3; ++m1)
          for (int m2 = 0; m2 < 3; ++m2)
            eps[m1][m2] += x[k] * variation[k].v[m1][m2];
      double s0[3][3];
      stress0(g.x, s0);
      const double(*tangent)[3][3][3] = nullptr; // the law's d sigma' / d eps
      if constexpr (WithLaw) {
        law_response = m.law->response(s0, history[q], eps);
        if (responses) responses[q] = law_response;
        tangent = law_response.tangent;
        // sigma + s0 below is the law's stress, which includes the initial stress.
        for (int m1 = 0; m1 < 3; ++m1)
          for (int m2 = 0; m2 < 3; ++m2)
            sigma[m1][m2] = law_response.stress[m1][m2] - s0[m1][m2];
      } else {
        physics::elasticStress(m.moduli, eps, sigma);
      }
      double p = 0.0, pdot = 0.0, grad_p[3] = {0, 0, 0}, grad_pdot[3] = {0, 0, 0}, div_udot = 0.0;
      if (with_pressure) {
        for (int a = 0; a < nv; ++a) {
          p += phi[a] * x[nu + a];
          pdot += phi[a] * xdot[nu + a];
          for (int d = 0; d < dim; ++d) {
            grad_p[d] += dphi[a * dim + d] * x[nu + a];
            grad_pdot[d] += dphi[a * dim + d] * xdot[nu + a];
          }
        }
        for (int k = 0; k < nu; ++k)
          div_udot += xdot[k] * div[k];
      } else if (m.porous) {
        p = pressure0(g.x); // drained: the pore pressure keeps its initial value
      }
      const double alpha = m.porous ? m.biot.biot_coefficient : 0.0;
      // R_u = (sigma'_0 + C:eps - alpha p I) : d eps - rho g . v
      double total[3][3];
      for (int m1 = 0; m1 < 3; ++m1)
        for (int m2 = 0; m2 < 3; ++m2)
          total[m1][m2] = s0[m1][m2] + sigma[m1][m2] - (m1 == m2 ? alpha * p : 0.0);
      for (int a = 0; a < nn; ++a)
        for (int i = 0; i < dim; ++i)
          F[a * dim + i] += w * (contract(total, a * dim + i) - m.density * gravity[i] * N[a]);
      if (with_pressure) {
        double flux[3];
        physics::darcyFlux(m.biot, dim, grad_p, gravity, flux);
        const double content = physics::fluidContentRate(m.biot, div_udot, pdot);
        for (int a = 0; a < nv; ++a) {
          double res = phi[a] * content;
          for (int d = 0; d < dim; ++d)
            res += dphi[a * dim + d] * (-flux[d] + m.stabilization * grad_pdot[d]);
          F[nu + a] += mass_scale * w * res;
        }
      }
      if (!J) continue;
      const int S = closure_size;
      if constexpr (WithLaw) {
        // stress_of[l] = C_t : variation[l]. C_t has the minor symmetries, so for the dof
        // (b, j) it is sum_n C_t[.][.][j][n] dN_b,n (+ C_t[.][.][2][2] N_b / r, hoop).
        // C_t may lack major symmetry (non-associated flow): every (k, l), no mirroring.
        for (int b = 0; b < nn; ++b)
          for (int j = 0; j < dim; ++j) {
            double(&ds)[3][3] = stress_of[b * dim + j].v;
            for (int m1 = 0; m1 < 3; ++m1)
              for (int m2 = 0; m2 < 3; ++m2) {
                double v = 0.0;
                for (int n = 0; n < dim; ++n)
                  v += tangent[m1][m2][j][n] * dN[b * dim + n];
                if (j == 0) v += tangent[m1][m2][2][2] * hoop[b];
                ds[m1][m2] = v;
              }
          }
        for (int k = 0; k < nu; ++k)
          for (int l = 0; l < nu; ++l)
            J[k * S + l] += w * contract(stress_of[l].v, k);
      } else
        // variation[k] : C : variation[l] is symmetric in k, l (C has major symmetry): the
        // upper triangle, mirrored.
        for (int k = 0; k < nu; ++k) {
          J[k * S + k] += w * contract(stress_of[k].v, k);
          for (int l = k + 1; l < nu; ++l) {
            const double v = w * contract(stress_of[l].v, k);
            J[k * S + l] += v;
            J[l * S + k] += v;
          }
        }
      if (!with_pressure) continue;
      // Couplings: displacement dofs (a, i) of the node basis against the vertex basis.
      for (int a = 0; a < nn; ++a)
        for (int b = 0; b < nv; ++b)
          for (int i = 0; i < dim; ++i) {
            J[(a * dim + i) * S + nu + b] += -w * alpha * div[a * dim + i] * phi[b];
            J[(nu + b) * S + a * dim + i] +=
                mass_scale * w * shift * alpha * phi[b] * div[a * dim + i];
          }
      for (int a = 0; a < nv; ++a)
        for (int b = 0; b < nv; ++b) {
          double grad_grad = 0.0;
          for (int d = 0; d < dim; ++d)
            grad_grad += dphi[a * dim + d] * dphi[b * dim + d];
          J[(nu + a) * S + nu + b] +=
              mass_scale * w *
              (shift * (m.biot.storage * phi[a] * phi[b] + m.stabilization * grad_grad) +
               m.biot.mobility * grad_grad);
        }
    }
  }
};

inline CellMaterial materialOf(const Scene &scene, const Region &r, double cell_size)
{
  CellMaterial m;
  m.moduli = physics::lameFromYoung(r.young, r.poisson);
  m.porous = r.porous();
  if (m.porous) {
    m.biot.biot_coefficient = r.biot_coefficient;
    m.biot.storage = r.storage;
    m.biot.mobility = r.permeability / scene.fluid_viscosity;
    m.biot.fluid_density = scene.fluid_density;
    m.density = physics::saturatedDensity(r.porosity, r.solid_density, scene.fluid_density);
    // Taylor-Hood (order 2) is inf-sup stable: the stabilisation of the equal-order pair
    // would only add an O(h^2) consistency error there.
    m.stabilization = scene.displacement_order == 1
                          ? physics::stabilizationParameter(m.biot, m.moduli, cell_size,
                                                            scene.stabilization_factor)
                          : 0.0;
  } else {
    m.density = r.solid_density;
  }
  return m;
}

} // namespace poroseam
