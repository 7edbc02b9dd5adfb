// The discrete problem on a distributed mesh: element loops over DMPlex closures for the
// residual and Jacobian of quasi-static Biot consolidation, boundary values, the initial
// (geostatic) state, and the integration-point history of the regions whose skeleton law has
// one (committed after accepted steps only). Point laws come from physics/, through the law
// table of skeleton_law.hpp for the skeleton.
#pragma once

#include "poroseam/cell_fields.hpp"
#include "poroseam/closure_cache.hpp"
#include "poroseam/geostatic.hpp"
#include "poroseam/interface_assembly.hpp"
#include "poroseam/kernel_work.hpp"
#include "poroseam/log_events.hpp"
#include "poroseam/reference_element.hpp"
#include "poroseam/scene.hpp"
#include "poroseam/skeleton_law.hpp"
#include <functional>
#include <map>
#include <petscdmplex.h>
#include <string>
#include <vector>

namespace poroseam {

/// How a residual is evaluated.
struct ResidualMode {
  /// Factor on the mass balance. The solver uses -dt S (see massBalanceScale): the coupling
  /// blocks then have opposite signs like a saddle point, and the rows are forces; 1 gives
  /// fluid volume rates [m3/s] for output.
  double mass_scale = 1.0;
  /// Include applied tractions and fluxes. Without them the residual at a vertex is the
  /// force (and water rate) the surroundings exert on the body there: reactions and outflows.
  bool include_loads = true;
  /// Time since the last accepted state (the step; for BDF's start-up half step, half of
  /// it), for rates of non-linear quantities such as the interface opening (see
  /// InterfaceRates); 0 when no step is involved.
  double dt = 0.0;
};

/// The integrator's difference formula applied to prescribed values: rate = now * value(t) +
/// sum_k weight[k] * (entry of state[k]), state[k] being local vectors of the earlier states
/// the integrator differentiates through (time_integration.hpp). Backward Euler: now = 1/dt,
/// weight[0] = -1/dt, state[0] the last accepted state.
struct RateStencil {
  double now = 0.0;
  int count = 0;
  double weight[2] = {0.0, 0.0};
  Vec state[2] = {nullptr, nullptr};
};

class Problem {
public:
  /// Precomputes cell and face lists, reference elements and boundary-value offsets.
  /// The DM must already have its solution section (createSolutionSection).
  PetscErrorCode setup(DM dm, const Scene &scene);

  /// Local vector with the initial state: zero displacement, hydrostatic (or zero) pressure.
  PetscErrorCode initialState(Vec local) const;

  /// Writes the prescribed values at time t into the constrained entries of `local`.
  PetscErrorCode insertBoundaryValues(double t, Vec local) const;
  /// Writes the rates of the prescribed values at time t, by `stencil`, into the constrained
  /// entries of `local_rate`.
  PetscErrorCode insertBoundaryRates(double t, const RateStencil &stencil, Vec local_rate) const;

  /// F(x, xdot) assembled into the local vector f (zeroed here).
  PetscErrorCode residual(double t, Vec local, Vec local_rate, const ResidualMode &mode,
                          Vec f) const;
  /// Destroys what the problem keeps between assemblies (before PetscFinalize).
  PetscErrorCode release();
  /// dF/dx + shift dF/dxdot assembled into J (zeroed here), with mode.mass_scale and mode.dt
  /// as in residual (mode.include_loads does not matter: loads do not depend on x).
  PetscErrorCode jacobian(double t, double shift, Vec local, Vec local_rate,
                          const ResidualMode &mode, Mat J) const;
  /// Whether the last jacobian() assembled exactly the matrix of the call before it (the
  /// same on every rank): a scene without interfaces or skeleton history at an unchanged
  /// shift and mass scale (fixed step), whose Jacobian is the copy of the cells' one. The
  /// solver then keeps its factorisation or preconditioner (-snes_keep_preconditioner).
  bool jacobianRepeated() const { return jacobian_repeated_; }

  /// Per-cell output of the state `local` (a local vector with boundary values inserted):
  /// effective_stress and total_stress [Pa] (full 3 x 3, tension positive) and strain [-],
  /// each averaged over the cell's integration points (src/assembly/cell_stress.hpp).
  PetscErrorCode cellFields(Vec local, CellFields &out) const;
  /// The bulk cells of this rank and the index in scene().regions of each.
  void cellRegions(std::vector<PetscInt> &cells, std::vector<int> &regions) const;

  /// Profiling: residual and Jacobian, bulk and interface terms, become -log_view events.
  void setLogEvents(const LogEvents &events) { events_ = events; }

  /// Commits integration-point history (interfaces, skeleton laws with history) of a
  /// converged state `local` (with its boundary values): only accepted steps are committed, so
  /// a failed step leaves the history of the last accepted one.
  PetscErrorCode commit(Vec local);
  const InterfaceAssembly &interfaces() const { return interfaces_; }
  /// Restores committed interface history from a checkpoint.
  PetscErrorCode restoreHistory(const std::vector<double> &values)
  {
    return interfaces_.restoreHistory(values);
  }
  /// The committed skeleton history of this rank's bulk integration points as plain numbers
  /// (for checkpoints, in this rank's cell order), its size, and back. Empty when no region's
  /// law has history.
  std::vector<double> committedSkeletonHistory() const;
  size_t skeletonHistoryValues() const { return skeleton_committed_.size() * kSkeletonValues; }
  PetscErrorCode restoreSkeletonHistory(const std::vector<double> &values);
  /// Some region's skeleton law has history (the same on every rank).
  bool hasSkeletonHistory() const { return any_skeleton_history_; }
  /// Visits this rank's bulk cells whose law has history with the law's response at `local`
  /// (with boundary values) from the committed history, as the assembly evaluates it: the mean
  /// equivalent plastic strain of the cell's integration points and its yield state (0 when
  /// every point is elastic, else the largest physics::YieldState code among them). Like the
  /// interface outputs, call it before committing the state.
  PetscErrorCode visitSkeletonCells(
      Vec local,
      const std::function<void(PetscInt cell, double equivalent_plastic_strain, int state)> &f)
      const;

  /// The terms of the applied tractions, fluxes and free water's load at time t (those the
  /// residual has with include_loads: -int t.v, +mass_scale int psi q_n), added into the local
  /// vector f. With `totals`: their sums over each of scene().boundaries, dim + 1 numbers per
  /// boundary: the force on the body [N] and the outflow times mass_scale, over this rank's
  /// faces (each face is on one rank).
  PetscErrorCode addLoads(double t, double mass_scale, Vec f, std::vector<double> *totals) const;

  /// Factor S [Pa/m] that turns the mass balance times dt (a volume) into a force: the largest
  /// constrained modulus of the porous regions over their mean cell size. The solver
  /// multiplies the mass balance by -dt S, one constant for all rows, so the discrete
  /// equations are unchanged but both kinds of residual row are forces.
  double massBalanceScale() const { return mass_balance_scale_; }

  /// Load factor shown in progress lines: the first ramped or tabulated condition, else 1.
  double loadFactor(double t) const;

  const Scene &scene() const { return *scene_; }
  DM dm() const { return dm_; }

  /// Initial pore pressure at a point (hydrostatic below the water level when gravity is on).
  double initialPressure(const double x[]) const;

private:
  struct BulkCell {
    PetscInt cell;
    int region;
    int element;
    double size;                 ///< h for the stabilisation
    size_t history = kNoHistory; ///< first of its points in skeleton_committed_
  };
  static constexpr size_t kNoHistory = (size_t)-1;
  /// Numbers per point in a checkpoint: the history's doubles.
  static constexpr size_t kSkeletonValues = sizeof(physics::SkeletonHistory) / sizeof(double);
  struct LoadedFace {
    PetscInt face;
    int condition; ///< index in scene.conditions, or kWaterLoad
    int element;
    double normal[3]; ///< outward unit normal (water load and normal pressure only)
    int boundary;     ///< index in scene.boundaries (-1: not one of them)
  };
  /// LoadedFace::condition of a face of -water_load_boundaries.
  static constexpr int kWaterLoad = -1;
  struct ConstrainedDof {
    PetscInt offset; ///< in the local vector
    int condition;
  };

  // setup's steps, in its order (problem.cpp; the bulk cells in problem_cells.cpp, the
  // constrained dofs in constrained_dofs.cpp).
  /// Forgets an earlier setup's lists and takes the scene's laws and water column.
  void takeScene(DM dm, const Scene &scene);
  /// The bulk cells of this rank (cells_) with their reference elements, sizes for the
  /// stabilisation and history slots, and each region's vertical extent [bottom, top] on this
  /// rank; `error` set for a cell of no region (then stops).
  PetscErrorCode collectBulkCells(std::vector<double> &bottom, std::vector<double> &top,
                                  std::string *error);
  /// -axisymmetric: `error` set for a vertex at x < 0 (x is the radius).
  PetscErrorCode checkAxisymmetricMesh(std::string *error) const;
  /// The closure cache of cells_.
  PetscErrorCode setupClosures();
  /// Curved cells (-mesh_geometry_order 2): node_places_, and no cell folds (collective).
  PetscErrorCode setupCurvedCells(MPI_Comm comm);
  /// mass_balance_scale_ from the cells' sizes and moduli (collective).
  PetscErrorCode setupMassBalanceScale(MPI_Comm comm);
  /// The local offsets of the dofs each Dirichlet condition sets (constrained_).
  PetscErrorCode collectConstrainedDofs();
  PetscErrorCode elementIndex(DMPolytopeType type, int *index);
  /// residual() without its log event (it has several exits).
  PetscErrorCode assembleResidual(double t, Vec local, Vec local_rate, const ResidualMode &mode,
                                  Vec f) const;
  void initialStress(const double x[], int region, double stress[3][3]) const;
  /// Initial total stress sigma'_0 - alpha p_0 I (for the interfaces' initial contact).
  void initialTotalStress(const double x[], int region, double stress[3][3]) const;
  /// The geostatic column from the ground regions' vertical extents, checked (collective).
  PetscErrorCode setupGeostatic(MPI_Comm comm, const std::vector<double> &bottom,
                                const std::vector<double> &top);
  /// Outward unit normal of a boundary face of `cell` (zero components beyond dim).
  PetscErrorCode outwardNormal(PetscInt face, PetscInt cell, double normal[3]) const;
  /// The faces with tractions or fluxes (boundary_loads.cpp), then those of the free water.
  PetscErrorCode setupLoadedFaces();
  /// The outward normal of a face of a -bc_<b>_pressure; `error` set when the face is inside
  /// the mesh or the boundary prescribes a displacement along its normal.
  PetscErrorCode pressureNormal(const BoundaryCondition &bc, PetscInt face, LoadedFace *f,
                                std::string *error) const;
  /// The faces of -water_load_boundaries with their outward normals, appended to faces_.
  PetscErrorCode setupWaterLoad(const std::vector<char> &ghost, PetscInt pStart);
  double gravityVector(int d) const;
  /// Work vectors of one cell, kept across the cells of an assembly loop.
  struct CellWork {
    std::vector<double> x, xdot, xc, F, K;
    CellKernelWork kernel;
  };
  /// Bulk terms of cell i, its closure read through closures_ from the local arrays of the
  /// solution u, its rate u_t and the coordinates: w.F, and with `with_jacobian` w.K
  /// (d/du + shift d/du_t). Shared by residual and Jacobian so both evaluate the same cell.
  /// `responses` (optional, for cells whose law has history): the law's response at each
  /// integration point.
  void cellTerms(size_t i, const PetscScalar *u, const PetscScalar *u_t, const PetscScalar *coords,
                 double mass_scale, double shift, bool with_jacobian, CellWork &w,
                 physics::SkeletonResponse *responses = nullptr) const;
  /// The law's responses at the integration points of every cell with history at `local`:
  /// visit(cell index, responses of its points). Zero rates (mechanics only).
  PetscErrorCode skeletonResponses(
      Vec local,
      const std::function<PetscErrorCode(size_t, const physics::SkeletonResponse *)> &visit) const;
  /// The initial effective stress must lie inside the yield surface of every law with history:
  /// checked at setup (collective).
  PetscErrorCode checkInitialYield(MPI_Comm comm);

  DM dm_ = nullptr;
  const Scene *scene_ = nullptr;
  int dim_ = 0;
  std::vector<ReferenceElement> elements_;
  std::map<int, int> element_of_type_;
  std::vector<BulkCell> cells_;
  ClosureCache closures_; ///< of cells_, same order
  /// Curved cells (-mesh_geometry_order 2): each displacement node's place at its dofs, in the
  /// local vectors' layout (displacementNodePlaces); empty for straight-sided cells.
  std::vector<double> node_places_;
  /// The geometry of cell i into xc: its nodes' places (curved) or its vertices' coordinates
  /// (from the local coordinate array `coords`); returns whether it is curved.
  bool cellGeometry(size_t i, const PetscScalar *coords, std::vector<double> &xc) const;
  std::vector<LoadedFace> faces_;
  std::vector<ConstrainedDof> constrained_;
  InterfaceAssembly interfaces_;
  std::vector<SkeletonLaw> laws_; ///< per region
  std::vector<physics::SkeletonHistory> skeleton_committed_;
  bool any_skeleton_history_ = false;
  physics::GeostaticColumn column_; ///< hydrostatic pressure, geostatic stresses, water load
  double mass_balance_scale_ = 1.0;
  LogEvents events_;
  /// The Jacobian of the cells without history, for the shift and mass scale it was
  /// assembled with (jacobian() copies it while they stay the same).
  mutable Mat linear_cells_jacobian_ = nullptr;
  mutable double linear_cells_shift_ = 0.0, linear_cells_mass_scale_ = 0.0;
  mutable bool jacobian_repeated_ = false; ///< jacobianRepeated()
};

} // namespace poroseam
