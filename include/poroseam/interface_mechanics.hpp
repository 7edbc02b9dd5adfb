// Mechanical assembly of zero-thickness interfaces on cohesive cells: the gap between the
// paired faces at integration points, the contact/friction law (physics/contact), and the
// integration-point history that is committed only after a converged step.
#pragma once

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
  double x[3] = {0, 0, 0};
  double weight = 0.0;     ///< area (length in 2D) it stands for
  double frame[3][3];      ///< e1 (normal, side 1 -> 2), e2, e3
  double gap_normal = 0.0; ///< g_N [m]
  double gap_tangential[2] = {0, 0};
  double opening = 0.0;           ///< mechanical opening o [m]
  double traction[3] = {0, 0, 0}; ///< on side 1 from side 2, global components [Pa]
  physics::ContactResponse response;
};

class InterfaceMechanics {
public:
  /// Initial effective stress of a region at a point (for the initial contact pressure).
  using InitialStress = std::function<void(const double x[], int region_tag, double s[3][3])>;

  PetscErrorCode setup(DM dm, const Scene &scene, InitialStress initial_stress);
  bool empty() const { return cells_.empty(); }

  /// Adds the interface forces to the local residual f (ADD_ALL_VALUES).
  PetscErrorCode residual(Vec local, Vec f) const;
  /// Adds the consistent (unsymmetric) tangent to J (no assembly here).
  PetscErrorCode jacobian(Vec local, Mat J) const;
  /// Stores the history of the converged state `local` (call after an accepted step only).
  PetscErrorCode commit(Vec local);

  /// Visits every integration point of this rank with its state at `local`.
  PetscErrorCode visit(Vec local, const std::function<void(int iface, int surface, PetscInt cell,
                                                           const InterfacePointState &)> &f) const;

private:
  struct Cell {
    PetscInt cell;
    int iface, surface, element;
    std::vector<int> side1_slot, side2_slot; ///< closure slots of paired vertices
    double frame[3][3];
    size_t history; ///< first entry in the history arrays
  };
  template <class Kernel> PetscErrorCode loop(Vec local, Kernel &&kernel) const;

  DM dm_ = nullptr;
  const Scene *scene_ = nullptr;
  int dim_ = 0;
  std::vector<ReferenceElement> elements_;
  std::vector<Cell> cells_;
  std::vector<physics::ContactInitial> initial_;
  std::vector<physics::ContactHistory> committed_;
};

} // namespace poroseam
