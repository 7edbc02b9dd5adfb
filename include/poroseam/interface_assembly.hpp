// Assembly of zero-thickness hydro-mechanical interfaces on cohesive cells: the gap between
// the paired faces at integration points, the contact/friction law (physics/contact), the
// three-node flow (physics/interface_flow) with the interface pressure p3 on the lateral
// edges, their couplings (p'_N + p3 on both faces, aperture and storage from the opening),
// and the integration-point history that is committed only after a converged step.
#pragma once

#include "poroseam/closure_cache.hpp"
#include "poroseam/contact.hpp"
#include "poroseam/reference_element.hpp"
#include "poroseam/scene.hpp"
#include <functional>
#include <petscdmplex.h>
#include <vector>

namespace poroseam {

/// What an integration point of an interface reports.
struct InterfacePointState {
  int point = 0;                       ///< integration point index within its cohesive cell
  int num_points = 0;                  ///< integration points of the cell
  int face_vertices = 0;               ///< vertices of the cell's side-1 face
  const double *face_coords = nullptr; ///< their coordinates (face_vertices x dim), face order
  /// Displacements of side 1 and side 2 at the same vertices (face_vertices x dim), for output.
  const double *face_displacement1 = nullptr;
  const double *face_displacement2 = nullptr;
  const double *phi = nullptr; ///< the face's vertex shape functions at the point (face_vertices)
  double x[3] = {0, 0, 0};
  /// Displacements of side 1 and side 2 at the point (node basis: exact at order 2 too).
  double displacement1[3] = {0, 0, 0}, displacement2[3] = {0, 0, 0};
  double weight = 0.0;     ///< area (length in 2D) it stands for
  double frame[3][3];      ///< e1 (normal, side 1 -> 2), e2, e3
  double gap_normal = 0.0; ///< g_N [m]
  double gap_tangential[2] = {0, 0};
  double opening = 0.0;           ///< mechanical opening o [m]
  double traction[3] = {0, 0, 0}; ///< on side 1 from side 2, global, p3 included [Pa]
  physics::ContactResponse response;
  // Hydraulics (interfaces with flow only; zero otherwise).
  bool flow = false;
  double interface_pressure = 0.0;         ///< p3 [Pa]
  double aperture = 0.0;                   ///< h = D0 + d + o [m] (d: shear dilation)
  double aperture_rate = 0.0;              ///< dh/dt [m/s]
  double longitudinal_flux[3] = {0, 0, 0}; ///< q_l, global [m2/s]
  double transversal_flux1 = 0.0;          ///< f_1 = T_1 (p1 - p3), side 1 -> inner [m/s]
  double transversal_flux2 = 0.0;          ///< f_2 = T_2 (p3 - p2), inner -> side 2 [m/s]
};

/// Rates for an evaluation: local vector of d/dt of the unknowns (the integrator's) and dt, the
/// time since the last accepted state: the opening rate is (o(g) - o(g - dt dg/dt)) / dt (the
/// difference of the openings under backward Euler; see InterfaceAssembly::loop for BDF2).
/// `rate` may be null (no flow terms are then evaluated: mechanics only, e.g. for committing
/// history).
struct InterfaceRates {
  Vec rate = nullptr;
  double dt = 0.0;
};

class InterfaceAssembly {
public:
  /// Initial total stress of a region at a point, sigma'_0 - alpha p_0 I (for the initial contact
  /// pressure and shear).
  using InitialStress = std::function<void(const double x[], int region_tag, double s[3][3])>;

  /// Initial (hydrostatic) pore pressure at a point.
  using InitialPressure = std::function<double(const double x[])>;

  PetscErrorCode setup(DM dm, const Scene &scene, InitialStress initial_stress,
                       InitialPressure initial_pressure);
  bool empty() const { return cells_.empty(); }

  /// Adds the interface terms to the local residual f (ADD_ALL_VALUES); the mass balances
  /// are multiplied by mass_scale like the bulk's.
  PetscErrorCode residual(Vec local, const InterfaceRates &rates, double mass_scale, Vec f) const;
  /// Adds the consistent (unsymmetric) tangent dF/dx + shift dF/dxdot to J (no assembly).
  PetscErrorCode jacobian(Vec local, const InterfaceRates &rates, double shift, double mass_scale,
                          Mat J) const;
  /// Stores the history of the converged state `local` (call after an accepted step only).
  PetscErrorCode commit(Vec local);
  /// The committed history of this rank's integration points as plain numbers (for
  /// checkpoints: kHistoryValues per point, in this rank's cell order), and back.
  static constexpr int kHistoryValues = 5;
  std::vector<double> committedHistory() const;
  size_t historyValues() const { return committed_.size() * kHistoryValues; }
  PetscErrorCode restoreHistory(const std::vector<double> &values);

  /// Where the contact law of some integration point of this rank changes branch (open /
  /// stick / slip) on the straight path from `local` (s = 0) to `local_end` (s = 1), both
  /// with their boundary values: appends those s in (0, 1] to `out` (unsorted).
  PetscErrorCode stateChanges(Vec local, Vec local_end, std::vector<double> &out) const;

  /// Visits every integration point of this rank with its state at `local`.
  PetscErrorCode visit(Vec local, const InterfaceRates &rates,
                       const std::function<void(int iface, int surface, PetscInt cell,
                                                const InterfacePointState &)> &f) const;

private:
  struct Cell {
    PetscInt cell;
    int iface, surface, element;
    int gauss_element; ///< Gauss rule of the same face, for lumped axisymmetric nodal weights
    /// Closure offsets of the first displacement component on side 1 and side 2 per node of
    /// the face element's node basis (its vertices at order 1; P2 / Q2 nodes at order 2).
    std::vector<int> u1, u2;
    /// Per side-1 face vertex a: closure offsets of the pressure on side 1 and 2 (-1: that
    /// side is not porous) and of p3 (-1: no flow), all linear (vertex basis); the offset of
    /// its first coordinate in the coordinate closure; the node that sits on it.
    std::vector<int> p1, p2, p3, x1, vertex_node;
    bool flow = false, porous1 = false, porous2 = false;
    /// Drained scene, interface without flow next to porous soil: the water in the gap keeps
    /// its initial (hydrostatic) pressure and pushes both faces, as p3 does with flow.
    bool gap_water = false;
    double frame[3][3];
    size_t history; ///< first entry in the history arrays
  };
  template <class Kernel>
  PetscErrorCode loop(Vec local, const InterfaceRates &rates, Kernel &&kernel) const;

  DM dm_ = nullptr;
  const Scene *scene_ = nullptr;
  int dim_ = 0;
  std::vector<ReferenceElement> elements_;
  std::vector<Cell> cells_;
  ClosureCache closures_; ///< of cells_, same order
  /// Curved faces (-mesh_geometry_order 2): side 1's node places of every cell (num_nodes x
  /// dim from cell index i * stride_), and the local frame of every integration point (the
  /// curved face's normal there and the cell's tangents turned onto it; 9 per history
  /// entry). Empty for straight faces, whose frame is the cell's.
  std::vector<double> places_, point_frames_;
  size_t places_stride_ = 0;
  /// The local frame of integration point h of `cell`.
  const double (*frameOf(const Cell &cell, size_t h) const)[3]
  {
    return point_frames_.empty() ? cell.frame
                                 : reinterpret_cast<const double(*)[3]>(&point_frames_[h * 9]);
  }
  /// Initial contact state of a point at x with frame `frame`, appended to initial_ and
  /// committed_ (or written at entry h when h < initial_.size()).
  void initialContact(const Interface &in, const double x[3], const double frame[3][3],
                      bool pore_water, size_t h);
  PetscErrorCode setupCurved(DM dm);
  std::vector<physics::ContactInitial> initial_;
  std::vector<physics::ContactHistory> committed_;
  InitialPressure initial_pressure_;
  InitialStress initial_stress_;
};

} // namespace poroseam
