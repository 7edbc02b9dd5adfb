#include "poroseam/interface_assembly.hpp"

#include "poroseam/closure_cache.hpp"
#include "poroseam/collective_check.hpp"
#include "poroseam/interface_flow.hpp"
#include "poroseam/interfaces.hpp"

#include <cmath>
#include <map>

namespace poroseam {
namespace {

/// Traction on side 1 in global components, t = -p'_N e1 + tau_k e_(k+1), and its derivative
/// with respect to the global gap g = u2 - u1.
void globalTraction(const physics::ContactResponse &r, const double e[3][3], int dim, double t[3],
                    double T[3][3])
{
  const double local[3] = {-r.contact_pressure_effective, r.shear[0], r.shear[1]};
  for (int i = 0; i < dim; ++i) {
    t[i] = 0.0;
    for (int k = 0; k < dim; ++k)
      t[i] += local[k] * e[k][i];
  }
  // d t_local / d g_local: the first row is -d p'_N / d g.
  double D[3][3];
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l)
      D[k][l] = (k == 0 ? -1.0 : 1.0) * r.tangent[k][l];
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) {
      double s = 0.0;
      for (int k = 0; k < dim; ++k)
        for (int l = 0; l < dim; ++l)
          s += e[k][i] * D[k][l] * e[l][j];
      T[i][j] = s;
    }
}

physics::ContactParameters contactParameters(const Interface &in)
{
  physics::ContactParameters p{in.normal_stiffness, in.tangential_stiffness, in.friction};
  p.dilation = in.dilation;
  p.dilation_slip_limit = in.dilation_slip_limit;
  return p;
}

} // namespace

/// Per-point quantities the flow Jacobian needs besides the reported state.
struct FlowPoint {
  double grad_phi[4][3]; ///< surface gradients of the face's shape functions
  double grad_p3[3];     ///< surface gradient of p3
  double gravity_t[3];   ///< tangential gravity
  double conductivity = 0.0, d_conductivity = 0.0;
  bool opening_active = false; ///< d o / d g_N = 1
  /// The same at the back-dated gap g_N - dt dg_N/dt of the storage rate (see loop()).
  bool back_opening_active = false;
  /// d h / d(g_N, g_T1, g_T2) through the dilation (local frame): non-zero only at a point in
  /// contact that slides with dilation.
  double d_aperture_dilation[3] = {0, 0, 0};
};

namespace {

/// Surface gradients grad_s phi_a = J (J^T J)^-1 grad_xi phi_a of a face element (dim - 1)
/// in space `dim`, at quadrature point q.
void surfaceGradients(const ReferenceElement &e, const double *x, int dim, int q, double g[4][3],
                      bool curved = false)
{
  const int m = e.dim, nv = e.num_vertices;
  const double *dphi = &e.basis_derivatives[q * nv * m];
  // The face's map (its vertices, or its nodes when curved: x holds their places):
  // J[r][k] = d x_r / d xi_k, the tangents of surfaceWeight.
  double t[2][3], J[3][2];
  surfaceTangents(e, x, dim, q, curved, t);
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 2; ++k)
      J[r][k] = t[k][r];
  double G[2][2] = {{0, 0}, {0, 0}}, Ginv[2][2];
  for (int k = 0; k < m; ++k)
    for (int l = 0; l < m; ++l)
      for (int r = 0; r < dim; ++r)
        G[k][l] += J[r][k] * J[r][l];
  if (m == 1)
    Ginv[0][0] = 1.0 / G[0][0];
  else {
    const double det = G[0][0] * G[1][1] - G[0][1] * G[1][0];
    Ginv[0][0] = G[1][1] / det, Ginv[1][1] = G[0][0] / det;
    Ginv[0][1] = -G[0][1] / det, Ginv[1][0] = -G[1][0] / det;
  }
  for (int a = 0; a < nv; ++a)
    for (int r = 0; r < 3; ++r) {
      double v = 0.0;
      if (r < dim)
        for (int k = 0; k < m; ++k)
          for (int l = 0; l < m; ++l)
            v += J[r][k] * Ginv[k][l] * dphi[a * m + l];
      g[a][r] = v;
    }
}

} // namespace

template <class Kernel>
PetscErrorCode InterfaceAssembly::loop(Vec local, const InterfaceRates &rates,
                                       Kernel &&kernel) const
{
  Vec coords;
  const PetscScalar *ua, *ra = nullptr, *ca;
  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinatesLocal(dm_, &coords));
  // Closures through the cache (closure_cache.hpp), read from the local arrays.
  PetscCall(VecGetArrayRead(local, &ua));
  if (rates.rate) PetscCall(VecGetArrayRead(rates.rate, &ra));
  PetscCall(VecGetArrayRead(coords, &ca));
  std::vector<double> x1, u1, u2, u_closure, udot_closure, nodal_phi;
  const double g = scene_->gravity;
  for (size_t i = 0; i < cells_.size(); ++i) {
    const Cell &cell = cells_[i];
    const Interface &in = scene_->interfaces[cell.iface];
    const physics::ContactParameters params = contactParameters(in);
    const ReferenceElement &e = elements_[cell.element];
    const bool flow = cell.flow && rates.rate;
    const int n = closures_.closureSize(i);
    u_closure.resize(n);
    gatherClosure(ua, closures_.local(i), n, u_closure.data());
    if (flow) {
      udot_closure.resize(n);
      gatherClosure(ra, closures_.local(i), n, udot_closure.data());
    }
    const double *u = u_closure.data(), *udot = udot_closure.data();
    // Side-1 vertex coordinates, and both faces' displacements at those vertices (output).
    const PetscInt *xc = closures_.coordinates(i);
    x1.resize(e.num_vertices * dim_);
    u1.resize(e.num_vertices * dim_);
    u2.resize(e.num_vertices * dim_);
    for (int a = 0; a < e.num_vertices; ++a)
      for (int d = 0; d < dim_; ++d) {
        x1[a * dim_ + d] = ca[xc[cell.x1[a] + d]];
        u1[a * dim_ + d] = u[cell.u1[cell.vertex_node[a]] + d];
        u2[a * dim_ + d] = u[cell.u2[cell.vertex_node[a]] + d];
      }
    // Curved faces: side 1's node places map the face (isoparametric).
    const bool curved = !places_.empty();
    const double *xg = curved ? &places_[i * places_stride_] : x1.data();
    for (int q = 0; q < e.num_quadrature; ++q) {
      // Vertex basis: geometry (straight faces), pressures, p3. Node basis: displacements, the
      // gap (and the geometry of curved faces).
      const double *phi = &e.basis[q * e.num_vertices];
      const double *N = &e.node_basis[q * e.num_nodes];
      const double(*frame)[3] = frameOf(cell, cell.history + q);
      InterfacePointState st;
      FlowPoint fp;
      st.point = q;
      st.num_points = e.num_quadrature;
      st.face_vertices = e.num_vertices;
      st.face_coords = x1.data();
      st.face_displacement1 = u1.data();
      st.face_displacement2 = u2.data();
      st.phi = phi;
      st.weight = surfaceWeight(e, xg, dim_, q, curved);
      if (scene_->axisymmetric) {
        // A ring: forces and flows are for the full circle, every term weighted here once.
        // Nodal points take the lumped weight int N_q 2 pi r ds of node q's function (node
        // basis, either order): the consistent nodal force of a uniform traction. At order 1
        // it keeps a spring at an axis vertex, where 2 pi r_q w_q would vanish; at order 2 it
        // is Simpson's 2 pi r_q w_q on a straight segment, zero at an axis vertex, as the
        // consistent force there is (docs/elements.md, quadratic interfaces in axisymmetry).
        if (in.nodal_integration) {
          const ReferenceElement &ge = elements_[cell.gauss_element];
          double lumped = 0.0;
          // The nodal point q is node q: its function from the node basis.
          nodal_phi.resize(ge.num_nodes);
          for (int k = 0; k < ge.num_quadrature; ++k) {
            double r = 0.0, xi[3];
            for (int a = 0; a < ge.num_vertices; ++a)
              r += ge.basis[k * ge.num_vertices + a] * x1[a * dim_];
            for (int d = 0; d < ge.dim; ++d)
              xi[d] = ge.quadrature_points[k * ge.dim + d];
            ge.evaluateNodes(xi, nodal_phi.data(), nullptr);
            lumped += surfaceWeight(ge, x1.data(), dim_, k) * nodal_phi[q] * 2.0 * M_PI * r;
          }
          st.weight = lumped;
        } else {
          double r = 0.0;
          for (int a = 0; a < e.num_vertices; ++a)
            r += phi[a] * x1[a * dim_];
          st.weight *= 2.0 * M_PI * r;
        }
      }
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          st.frame[i][j] = frame[i][j];
      double gap[3] = {0, 0, 0}, gap_rate[3] = {0, 0, 0};
      // The gap from the nodes' jumps (not the difference of the two faces' displacements,
      // which would lose digits to a large common motion).
      for (int a = 0; a < e.num_nodes; ++a)
        for (int d = 0; d < dim_; ++d) {
          gap[d] += N[a] * (u[cell.u2[a] + d] - u[cell.u1[a] + d]);
          if (flow) gap_rate[d] += N[a] * (udot[cell.u2[a] + d] - udot[cell.u1[a] + d]);
          st.displacement1[d] += N[a] * u[cell.u1[a] + d];
          st.displacement2[d] += N[a] * u[cell.u2[a] + d];
        }
      for (int a = 0; a < (curved ? e.num_nodes : e.num_vertices); ++a)
        for (int d = 0; d < dim_; ++d)
          st.x[d] += (curved ? N : phi)[a] * xg[a * dim_ + d];
      double local_gap[3] = {0, 0, 0};
      for (int k = 0; k < dim_; ++k)
        for (int d = 0; d < dim_; ++d)
          local_gap[k] += frame[k][d] * gap[d];
      st.gap_normal = local_gap[0];
      st.gap_tangential[0] = local_gap[1];
      st.gap_tangential[1] = local_gap[2];
      const size_t h = cell.history + q;
      st.response = physics::contactResponse(params, initial_[h], committed_[h], dim_ - 1,
                                             st.gap_normal, st.gap_tangential);
      st.opening =
          physics::mechanicalOpening(params, initial_[h], st.gap_normal, st.response.dilation);
      double T[3][3];
      globalTraction(st.response, frame, dim_, st.traction, T);
      if (cell.gap_water) {
        // Total normal pressure p'_N + p_w with the gap water at its hydrostatic pressure
        // (fixed: no contribution to the tangent).
        const double pw = initial_pressure_(st.x);
        st.interface_pressure = pw;
        for (int d = 0; d < dim_; ++d)
          st.traction[d] -= pw * frame[0][d];
      }
      if (flow) {
        st.flow = true;
        surfaceGradients(e, xg, dim_, q, fp.grad_phi, curved);
        double p1 = 0.0, p2 = 0.0;
        for (int d = 0; d < 3; ++d)
          fp.grad_p3[d] = 0.0;
        for (int a = 0; a < e.num_vertices; ++a) {
          st.interface_pressure += phi[a] * u[cell.p3[a]];
          for (int d = 0; d < dim_; ++d)
            fp.grad_p3[d] += fp.grad_phi[a][d] * u[cell.p3[a]];
          if (cell.porous1) p1 += phi[a] * u[cell.p1[a]];
          if (cell.porous2) p2 += phi[a] * u[cell.p2[a]];
        }
        // Total normal pressure p'_N + p3 on both faces (friction uses p'_N only).
        for (int d = 0; d < dim_; ++d)
          st.traction[d] -= st.interface_pressure * frame[0][d];
        // Aperture and its rate. The opening o = max(0, g_N - c) is not differentiable where
        // the gap closes, so its rate is the secant over the step of the integrator's own gap
        // rate: with dt the time since the last accepted state and g_b = g_N - dt dg_N/dt,
        //   do/dt = (o(g_N) - o(g_b)) / dt = dg_N/dt * (mean of do/dg over [g_b, g_N]).
        // Backward Euler: g_b is the last accepted gap, so this is the difference of the
        // openings and the gap's water balance telescopes exactly. BDF2 (or any integrator
        // whose gap rate is second order): g_b = g_N(t - dt) + O(dt^2), and wherever the point
        // stays open (o linear in g) the rate is exactly the integrator's dg_N/dt, the storage
        // term its own second-order derivative of h; it stays zero where the point stays
        // closed. Only a step in which the point opens or closes takes a secant, where the
        // opening has a kink in time and no method keeps its order. The BDF formula on h itself
        // would need the openings of the last two states at every point, and the chain rule
        // do/dg dg/dt would store water (g_N - g_prev instead of o) in the step that opens.
        // With shear dilation d the aperture is h = D0 + d + o (o measured from the dilated
        // contact position), and the back-dated state has the dilation of the last accepted
        // state d_n: dh/dt = ((d - d_n) + (o - o_b)) / dt. The dilation's part is a backward
        // difference under any integrator (d is history, not an unknown with a rate); it
        // telescopes over the steps like the opening's under backward Euler.
        double gn_rate = 0.0;
        for (int d = 0; d < dim_; ++d)
          gn_rate += frame[0][d] * gap_rate[d];
        const double dilation_n = physics::dilation(params, committed_[h].slip_plastic);
        const double back_opening = physics::mechanicalOpening(
            params, initial_[h], st.gap_normal - rates.dt * gn_rate, dilation_n);
        fp.opening_active = st.opening > 0.0;
        fp.back_opening_active = back_opening > 0.0;
        if (!fp.opening_active)
          for (int k = 0; k < 3; ++k)
            fp.d_aperture_dilation[k] = st.response.d_dilation[k];
        st.aperture = in.aperture0 + st.response.dilation + st.opening;
        st.aperture_rate =
            rates.dt > 0.0
                ? ((st.response.dilation - dilation_n) + (st.opening - back_opening)) / rates.dt
                : 0.0;
        const auto c = physics::cubicLawConductivity(st.aperture, scene_->fluid_viscosity);
        fp.conductivity = c.value;
        fp.d_conductivity = c.d_aperture;
        double gdotn = 0.0;
        for (int d = 0; d < dim_; ++d)
          gdotn += (d == dim_ - 1 ? -g : 0.0) * frame[0][d];
        for (int d = 0; d < 3; ++d)
          fp.gravity_t[d] = (d == dim_ - 1 ? -g : 0.0) * (d < dim_) - gdotn * frame[0][d];
        physics::longitudinalFlux(c.value, dim_, fp.grad_p3, fp.gravity_t, scene_->fluid_density,
                                  st.longitudinal_flux);
        if (cell.porous1)
          st.transversal_flux1 =
              physics::transversalFlux(in.transmissivity1, p1, st.interface_pressure);
        if (cell.porous2)
          st.transversal_flux2 =
              physics::transversalFlux(in.transmissivity2, st.interface_pressure, p2);
      }
      PetscCall(kernel(cell, q, phi, N, st, fp, T, n));
    }
  }
  PetscCall(VecRestoreArrayRead(coords, &ca));
  if (rates.rate) PetscCall(VecRestoreArrayRead(rates.rate, &ra));
  PetscCall(VecRestoreArrayRead(local, &ua));
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceAssembly::residual(Vec local, const InterfaceRates &rates,
                                           double mass_scale, Vec f) const
{
  std::vector<double> F;
  PetscScalar *fa;
  PetscFunctionBeginUser;
  PetscCall(VecGetArray(f, &fa));
  const Cell *current = nullptr;
  auto flush = [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    // DMPlexVecSetClosure(ADD_ALL_VALUES) through the closure cache.
    if (current) {
      const size_t i = current - cells_.data();
      addClosure(F.data(), closures_.local(i), closures_.closureSize(i), fa);
    }
    PetscFunctionReturn(0);
  };
  PetscCall(loop(local, rates,
                 [&](const Cell &cell, int, const double *phi, const double *N,
                     const InterfacePointState &st, const FlowPoint &fp, const double[3][3],
                     int n) -> PetscErrorCode {
                   PetscFunctionBeginUser;
                   if (&cell != current) {
                     PetscCall(flush());
                     current = &cell;
                     F.assign(n, 0.0);
                   }
                   const int nu = (int)cell.u1.size(), nf = (int)cell.p3.size();
                   const double w = st.weight;
                   // The interface pushes side 1 with t and side 2 with -t; residual = -force.
                   for (int a = 0; a < nu; ++a)
                     for (int d = 0; d < dim_; ++d) {
                       F[cell.u1[a] + d] -= w * N[a] * st.traction[d];
                       F[cell.u2[a] + d] += w * N[a] * st.traction[d];
                     }
                   if (!st.flow) PetscFunctionReturn(0);
                   // Interface balance dh/dt + div q_l = f1 - f2 (weak form, volumetric), and
                   // f1 leaving side 1, f2 entering side 2.
                   const double ws = mass_scale * w;
                   const double net = st.transversal_flux1 - st.transversal_flux2;
                   for (int a = 0; a < nf; ++a) {
                     double div = 0.0;
                     for (int d = 0; d < dim_; ++d)
                       div += fp.grad_phi[a][d] * st.longitudinal_flux[d];
                     F[cell.p3[a]] += ws * (phi[a] * (st.aperture_rate - net) - div);
                     if (cell.porous1) F[cell.p1[a]] += ws * phi[a] * st.transversal_flux1;
                     if (cell.porous2) F[cell.p2[a]] -= ws * phi[a] * st.transversal_flux2;
                   }
                   PetscFunctionReturn(0);
                 }));
  PetscCall(flush());
  PetscCall(VecRestoreArray(f, &fa));
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceAssembly::jacobian(Vec local, const InterfaceRates &rates, double shift,
                                           double mass_scale, Mat J) const
{
  std::vector<double> K;
  std::vector<PetscInt> rows;
  PetscFunctionBeginUser;
  const Cell *current = nullptr;
  int size = 0;
  auto flush = [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    // DMPlexMatSetClosure through the closure cache: the same indices, one MatSetValues.
    if (current) {
      rows.resize(size);
      closures_.globalIndices(current - cells_.data(), rows.data());
      PetscCall(MatSetValues(J, size, rows.data(), size, rows.data(), K.data(), ADD_VALUES));
    }
    PetscFunctionReturn(0);
  };
  PetscCall(loop(local, rates,
                 [&](const Cell &cell, int, const double *phi, const double *N,
                     const InterfacePointState &st, const FlowPoint &fp, const double T[3][3],
                     int n) -> PetscErrorCode {
                   PetscFunctionBeginUser;
                   if (&cell != current) {
                     PetscCall(flush());
                     current = &cell;
                     size = n;
                     K.assign((size_t)n * n, 0.0);
                   }
                   auto add = [&](int row, int col, double v) { K[(size_t)row * size + col] += v; };
                   const Interface &in = scene_->interfaces[cell.iface];
                   const int nu = (int)cell.u1.size(), nf = (int)cell.p3.size();
                   const double w = st.weight;
                   const double *e1 = st.frame[0];
                   // Contact: R_1a = -w N_a t(g), R_2a = +w N_a t(g), g = sum N_b (u_2b - u_1b)
                   // over the displacement nodes.
                   for (int a = 0; a < nu; ++a)
                     for (int b = 0; b < nu; ++b) {
                       const double wab = w * N[a] * N[b];
                       const int rows[2] = {cell.u1[a], cell.u2[a]};
                       const int cols[2] = {cell.u1[b], cell.u2[b]};
                       const double sign[2] = {-1.0, 1.0};
                       for (int r = 0; r < 2; ++r)
                         for (int c = 0; c < 2; ++c)
                           for (int i = 0; i < dim_; ++i)
                             for (int j = 0; j < dim_; ++j)
                               add(rows[r] + i, cols[c] + j, sign[r] * sign[c] * wab * T[i][j]);
                     }
                   if (!st.flow) PetscFunctionReturn(0);
                   const double ws = mass_scale * w;
                   // d q_l / d h (h depends on u through the opening).
                   double dq_dh[3];
                   for (int d = 0; d < 3; ++d)
                     dq_dh[d] = -fp.d_conductivity *
                                (fp.grad_p3[d] - scene_->fluid_density * fp.gravity_t[d]);
                   const double active = fp.opening_active ? 1.0 : 0.0;
                   // d(do/dt)/dg_N with dg_b/dg_N = 1 - dt shift (the gap rate moves with the
                   // gap by shift): (active - back) / dt + shift back. Backward Euler
                   // (dt shift = 1): shift active.
                   const double back = fp.back_opening_active ? 1.0 : 0.0;
                   const double d_storage =
                       rates.dt > 0.0 ? (active - back) / rates.dt + shift * back : 0.0;
                   // Through the dilation of a sliding point in contact (h moves with d, which
                   // follows every gap component): its global gradient.
                   double dh_dilation[3] = {0, 0, 0};
                   bool dilating = false;
                   for (int k = 0; k < dim_; ++k)
                     for (int j = 0; j < dim_; ++j) {
                       dh_dilation[j] += fp.d_aperture_dilation[k] * st.frame[k][j];
                       dilating = dilating || fp.d_aperture_dilation[k] != 0.0;
                     }
                   const double inv_dt = rates.dt > 0.0 ? 1.0 / rates.dt : 0.0;
                   // p3 (vertex basis) on both faces (node basis): R_u1 += w N p3 e1,
                   // R_u2 -= w N p3 e1.
                   for (int a = 0; a < nu; ++a)
                     for (int b = 0; b < nf; ++b)
                       for (int i = 0; i < dim_; ++i) {
                         add(cell.u1[a] + i, cell.p3[b], w * N[a] * phi[b] * e1[i]);
                         add(cell.u2[a] + i, cell.p3[b], -w * N[a] * phi[b] * e1[i]);
                       }
                   for (int a = 0; a < nf; ++a) {
                     double gq = 0.0;
                     for (int d = 0; d < dim_; ++d)
                       gq += fp.grad_phi[a][d] * dq_dh[d];
                     // Storage dh/dt and conductivity through the opening (rows: p3 at the
                     // vertices; columns: the displacement nodes): d/du_2 = +, d/du_1 = -.
                     for (int b = 0; b < nu; ++b) {
                       const double du = ws * (d_storage * phi[a] - active * gq) * N[b];
                       for (int j = 0; j < dim_; ++j) {
                         add(cell.p3[a], cell.u2[b] + j, du * e1[j]);
                         add(cell.p3[a], cell.u1[b] + j, -du * e1[j]);
                       }
                       if (!dilating) continue;
                       const double dd = ws * (inv_dt * phi[a] - gq) * N[b];
                       for (int j = 0; j < dim_; ++j) {
                         add(cell.p3[a], cell.u2[b] + j, dd * dh_dilation[j]);
                         add(cell.p3[a], cell.u1[b] + j, -dd * dh_dilation[j]);
                       }
                     }
                   }
                   for (int a = 0; a < nf; ++a)
                     for (int b = 0; b < nf; ++b) {
                       const double pp = phi[a] * phi[b];
                       double gg = 0.0;
                       for (int d = 0; d < dim_; ++d)
                         gg += fp.grad_phi[a][d] * fp.grad_phi[b][d];
                       // Interface balance row.
                       add(cell.p3[a], cell.p3[b],
                           ws * (fp.conductivity * gg + (in.transmissivity1 * cell.porous1 +
                                                         in.transmissivity2 * cell.porous2) *
                                                            pp));
                       if (cell.porous1) {
                         add(cell.p3[a], cell.p1[b], -ws * in.transmissivity1 * pp);
                         add(cell.p1[a], cell.p1[b], ws * in.transmissivity1 * pp);
                         add(cell.p1[a], cell.p3[b], -ws * in.transmissivity1 * pp);
                       }
                       if (cell.porous2) {
                         add(cell.p3[a], cell.p2[b], -ws * in.transmissivity2 * pp);
                         add(cell.p2[a], cell.p2[b], ws * in.transmissivity2 * pp);
                         add(cell.p2[a], cell.p3[b], -ws * in.transmissivity2 * pp);
                       }
                     }
                   PetscFunctionReturn(0);
                 }));
  PetscCall(flush());
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceAssembly::commit(Vec local)
{
  std::vector<physics::ContactHistory> updated = committed_;
  PetscFunctionBeginUser;
  PetscCall(loop(local, InterfaceRates{},
                 [&](const Cell &cell, int q, const double *, const double *,
                     const InterfacePointState &st, const FlowPoint &, const double[3][3],
                     int) -> PetscErrorCode {
                   updated[cell.history + q] = st.response.updated;
                   return 0;
                 }));
  committed_.swap(updated);
  PetscFunctionReturn(0);
}

std::vector<double> InterfaceAssembly::committedHistory() const
{
  static_assert(sizeof(physics::ContactHistory) == kHistoryValues * sizeof(double),
                "ContactHistory changed: update kHistoryValues and the copies below");
  std::vector<double> values;
  values.reserve(committed_.size() * kHistoryValues);
  for (const auto &h : committed_)
    values.insert(values.end(), {h.gap_tangential[0], h.gap_tangential[1], h.shear[0], h.shear[1],
                                 h.slip_plastic});
  return values;
}

PetscErrorCode InterfaceAssembly::restoreHistory(const std::vector<double> &values)
{
  PetscFunctionBeginUser;
  PetscCheck(values.size() == historyValues(), PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "interface history of %zu values for %zu integration points", values.size(),
             committed_.size());
  for (size_t i = 0; i < committed_.size(); ++i) {
    const double *v = &values[i * kHistoryValues];
    committed_[i].gap_tangential[0] = v[0], committed_[i].gap_tangential[1] = v[1];
    committed_[i].shear[0] = v[2], committed_[i].shear[1] = v[3];
    committed_[i].slip_plastic = v[4];
  }
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceAssembly::stateChanges(Vec local, Vec local_end,
                                               std::vector<double> &out) const
{
  std::vector<double> gaps(3 * committed_.size(), 0.0);
  PetscFunctionBeginUser;
  PetscCall(loop(local, InterfaceRates{},
                 [&](const Cell &cell, int q, const double *, const double *,
                     const InterfacePointState &st, const FlowPoint &, const double[3][3],
                     int) -> PetscErrorCode {
                   double *g = &gaps[3 * (cell.history + q)];
                   g[0] = st.gap_normal, g[1] = st.gap_tangential[0], g[2] = st.gap_tangential[1];
                   return 0;
                 }));
  PetscCall(loop(local_end, InterfaceRates{},
                 [&](const Cell &cell, int q, const double *, const double *,
                     const InterfacePointState &st, const FlowPoint &, const double[3][3],
                     int) -> PetscErrorCode {
                   const size_t h = cell.history + q;
                   const double *g = &gaps[3 * h];
                   const double d[3] = {st.gap_normal - g[0], st.gap_tangential[0] - g[1],
                                        st.gap_tangential[1] - g[2]};
                   const physics::ContactParameters params =
                       contactParameters(scene_->interfaces[cell.iface]);
                   physics::contactStateChanges(params, initial_[h], committed_[h], dim_ - 1, g[0],
                                                g + 1, d[0], d + 1, out);
                   return 0;
                 }));
  PetscFunctionReturn(0);
}

PetscErrorCode InterfaceAssembly::visit(
    Vec local, const InterfaceRates &rates,
    const std::function<void(int, int, PetscInt, const InterfacePointState &)> &f) const
{
  PetscFunctionBeginUser;
  PetscCall(loop(local, rates,
                 [&](const Cell &cell, int, const double *, const double *,
                     const InterfacePointState &st, const FlowPoint &, const double[3][3],
                     int) -> PetscErrorCode {
                   f(cell.iface, cell.surface, cell.cell, st);
                   return 0;
                 }));
  PetscFunctionReturn(0);
}

} // namespace poroseam
