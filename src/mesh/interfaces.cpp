#include "poroseam/interfaces.hpp"
#include "poroseam/curved_nodes.hpp"

#include "poroseam/collective_check.hpp"
#include "poroseam/reference_element.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace poroseam {

bool isCohesive(DMPolytopeType t)
{
  return t == DM_POLYTOPE_POINT_PRISM_TENSOR || t == DM_POLYTOPE_SEG_PRISM_TENSOR ||
         t == DM_POLYTOPE_TRI_PRISM_TENSOR || t == DM_POLYTOPE_QUAD_PRISM_TENSOR;
}

namespace {

PetscErrorCode closureCoordinates(DM dm, PetscInt point, std::vector<double> &x)
{
  Vec coords;
  PetscSection csec;
  PetscScalar *values = nullptr;
  PetscInt n = 0;
  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetCoordinateSection(dm, &csec));
  PetscCall(DMPlexVecGetClosure(dm, csec, coords, point, &n, &values));
  x.assign(values, values + n);
  PetscCall(DMPlexVecRestoreClosure(dm, csec, coords, point, &n, &values));
  PetscFunctionReturn(0);
}

void centroid(const std::vector<double> &x, int dim, double c[3])
{
  const int nv = (int)x.size() / dim;
  c[0] = c[1] = c[2] = 0.0;
  for (int a = 0; a < nv; ++a)
    for (int d = 0; d < dim; ++d)
      c[d] += x[a * dim + d] / nv;
}


/// Tips of interfaces that end inside the mesh: the rim of the interface (points of
/// dimension dim - 2 that bound only one interface face: vertices in 2D, edges in 3D), where
/// not on the boundary of the mesh, completed with their vertices.
PetscErrorCode markBuriedTips(DM dm, DMLabel faces, DMLabel buried)
{
  PetscInt dim;
  PetscFunctionBeginUser;
  PetscCall(DMGetDimension(dm, &dim));
  DMLabel meshBoundary;
  PetscCall(DMLabelCreate(PETSC_COMM_SELF, "mesh boundary", &meshBoundary));
  PetscCall(DMPlexMarkBoundaryFaces(dm, 1, meshBoundary));
  PetscCall(DMPlexLabelComplete(dm, meshBoundary));
  PetscInt rStart, rEnd, fStart, fEnd;
  PetscCall(DMPlexGetDepthStratum(dm, dim - 2, &rStart, &rEnd));
  PetscCall(DMPlexGetHeightStratum(dm, 1, &fStart, &fEnd));
  std::map<PetscInt, int> count;
  for (PetscInt f = fStart; f < fEnd; ++f) {
    PetscInt marked;
    PetscCall(DMLabelGetValue(faces, f, &marked));
    if (marked != 1) continue;
    PetscInt n, *pts = nullptr;
    PetscCall(DMPlexGetTransitiveClosure(dm, f, PETSC_TRUE, &n, &pts));
    for (PetscInt i = 0; i < n; ++i)
      if (pts[2 * i] >= rStart && pts[2 * i] < rEnd) ++count[pts[2 * i]];
    PetscCall(DMPlexRestoreTransitiveClosure(dm, f, PETSC_TRUE, &n, &pts));
  }
  for (const auto &[point, n] : count) {
    PetscInt onBoundary;
    PetscCall(DMLabelGetValue(meshBoundary, point, &onBoundary));
    if (n == 1 && onBoundary != 1) PetscCall(DMLabelSetValue(buried, point, 1));
  }
  PetscCall(DMPlexLabelComplete(dm, buried));
  PetscCall(DMLabelDestroy(&meshBoundary));
  PetscFunctionReturn(0);
}

/// Every face of an interface must have a cell on each side: a face group on the outer
/// boundary of the mesh would give cohesive cells with one side (and meaningless forces).
/// Collective; the mesh is still whole on rank 0 here.
PetscErrorCode checkInterfacesInside(DM dm, const Scene &scene, DMLabel faceSets)
{
  MPI_Comm comm;
  std::string error;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetComm((PetscObject)dm, &comm));
  for (const auto &in : scene.interfaces)
    for (size_t s = 0; s < in.tags.size() && error.empty(); ++s) {
      IS is = nullptr;
      PetscCall(DMLabelGetStratumIS(faceSets, in.tags[s], &is));
      if (!is) continue;
      const PetscInt *idx;
      PetscInt n, outer = 0, total = 0;
      double where[3] = {0, 0, 0};
      PetscCall(ISGetLocalSize(is, &n));
      PetscCall(ISGetIndices(is, &idx));
      PetscInt fStart, fEnd;
      PetscCall(DMPlexGetHeightStratum(dm, 1, &fStart, &fEnd));
      for (PetscInt k = 0; k < n; ++k) {
        if (idx[k] < fStart || idx[k] >= fEnd) continue; // not a face (a vertex of a group)
        PetscInt support;
        PetscCall(DMPlexGetSupportSize(dm, idx[k], &support));
        ++total;
        if (support < 2 && outer++ == 0) {
          std::vector<double> x;
          PetscCall(closureCoordinates(dm, idx[k], x));
          PetscInt dim;
          PetscCall(DMGetDimension(dm, &dim));
          centroid(x, (int)dim, where);
        }
      }
      PetscCall(ISRestoreIndices(is, &idx));
      PetscCall(ISDestroy(&is));
      if (outer) {
        std::ostringstream msg;
        msg << "interface '" << in.name << "': " << outer << " of the " << total
            << " faces of its face group '" << in.surfaces[s] << "' (-interface_" << in.name
            << "_surfaces) lie on the outer boundary of the "
            << "mesh, with a cell on one side only (the first near (" << where[0] << ", "
            << where[1] << ", " << where[2] << ")): an interface must lie inside the mesh, "
            << "between two cells; for a boundary use -boundaries";
        error = msg.str();
      }
    }
  PetscCall(checkOnAllRanks(comm, error));
  PetscFunctionReturn(0);
}

/// Interface faces must form manifolds: where three or more meet at one ridge (a vertex in 2D,
/// an edge in 3D: a T-junction or a star) there is no "side 1" and "side 2", and PETSc's
/// orientation of the interface stops with a traceback. Collective; rank 0 holds the mesh.
PetscErrorCode checkInterfaceJunctions(DM dm, const Scene &scene, DMLabel faceSets, DMLabel faces)
{
  MPI_Comm comm;
  PetscInt dim;
  std::string error;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetComm((PetscObject)dm, &comm));
  PetscCall(DMGetDimension(dm, &dim));
  PetscInt rStart, rEnd, fStart, fEnd;
  PetscCall(DMPlexGetDepthStratum(dm, dim - 2, &rStart, &rEnd));
  PetscCall(DMPlexGetHeightStratum(dm, 1, &fStart, &fEnd));
  std::map<PetscInt, std::vector<PetscInt>> facesAt; // ridge -> interface faces
  for (PetscInt f = fStart; f < fEnd; ++f) {
    PetscInt marked;
    PetscCall(DMLabelGetValue(faces, f, &marked));
    if (marked != 1) continue;
    PetscInt n, *pts = nullptr;
    PetscCall(DMPlexGetTransitiveClosure(dm, f, PETSC_TRUE, &n, &pts));
    for (PetscInt i = 0; i < n; ++i)
      if (pts[2 * i] >= rStart && pts[2 * i] < rEnd) facesAt[pts[2 * i]].push_back(f);
    PetscCall(DMPlexRestoreTransitiveClosure(dm, f, PETSC_TRUE, &n, &pts));
  }
  for (const auto &[ridge, list] : facesAt) {
    if (list.size() <= 2) continue;
    std::vector<double> x;
    double where[3] = {0, 0, 0};
    PetscCall(closureCoordinates(dm, ridge, x));
    centroid(x, (int)dim, where);
    std::vector<std::string> groups;
    for (PetscInt f : list) {
      PetscInt tag;
      PetscCall(DMLabelGetValue(faceSets, f, &tag));
      for (const auto &in : scene.interfaces)
        for (size_t k = 0; k < in.tags.size(); ++k)
          if (in.tags[k] == tag) {
            const std::string g = "'" + in.surfaces[k] + "' (interface '" + in.name + "')";
            if (std::find(groups.begin(), groups.end(), g) == groups.end()) groups.push_back(g);
          }
    }
    std::ostringstream msg;
    msg << list.size() << " interface faces of the face group" << (groups.size() > 1 ? "s " : " ");
    for (size_t k = 0; k < groups.size(); ++k)
      msg << (k ? (k + 1 == groups.size() ? " and " : ", ") : "") << groups[k];
    msg << " meet at the " << (dim == 2 ? "vertex" : "edge") << " near (" << where[0] << ", "
        << where[1] << ", " << where[2] << "): a T-junction or crossing, where an interface "
        << "has no two sides; the interface faces of a scene must not branch (end one "
        << "branch short of the junction, or leave it out of the interface groups)";
    error = msg.str();
    break;
  }
  PetscCall(checkOnAllRanks(comm, error));
  PetscFunctionReturn(0);
}

} // namespace

PetscErrorCode bulkNeighbour(DM dm, PetscInt face, PetscInt *cell)
{
  const PetscInt *support;
  PetscInt size;
  PetscFunctionBeginUser;
  *cell = -1;
  PetscCall(DMPlexGetSupportSize(dm, face, &size));
  PetscCall(DMPlexGetSupport(dm, face, &support));
  for (PetscInt i = 0; i < size; ++i) {
    DMPolytopeType t;
    PetscCall(DMPlexGetCellType(dm, support[i], &t));
    if (!isCohesive(t)) *cell = support[i];
  }
  PetscFunctionReturn(0);
}

PetscErrorCode splitInterfaces(DM *dm, const Scene &scene)
{
  PetscInt dim;
  MPI_Comm comm;
  PetscFunctionBeginUser;
  if (scene.interfaces.empty()) PetscFunctionReturn(0);
  PetscCall(PetscObjectGetComm((PetscObject)*dm, &comm));
  PetscCall(DMGetDimension(*dm, &dim));
  DMLabel faceSets;
  PetscCall(DMGetLabel(*dm, "Face Sets", &faceSets));
  PetscCheck(faceSets, comm, PETSC_ERR_USER_INPUT, "the mesh has no face groups to split along");

  // Interface faces, marked with value 1 and completed to their closure.
  DMLabel faces;
  PetscCall(DMLabelCreate(PETSC_COMM_SELF, "interface faces", &faces));
  std::map<int, std::pair<int, int>> surfaceOfTag; // tag -> (interface, surface)
  for (size_t i = 0; i < scene.interfaces.size(); ++i)
    for (size_t s = 0; s < scene.interfaces[i].tags.size(); ++s) {
      surfaceOfTag[scene.interfaces[i].tags[s]] = {(int)i, (int)s};
      IS is = nullptr;
      PetscCall(DMLabelGetStratumIS(faceSets, scene.interfaces[i].tags[s], &is));
      if (!is) continue;
      const PetscInt *idx;
      PetscInt n;
      PetscCall(ISGetLocalSize(is, &n));
      PetscCall(ISGetIndices(is, &idx));
      for (PetscInt k = 0; k < n; ++k)
        PetscCall(DMLabelSetValue(faces, idx[k], 1));
      PetscCall(ISRestoreIndices(is, &idx));
      PetscCall(ISDestroy(&is));
    }
  PetscCall(DMPlexLabelComplete(*dm, faces));
  PetscCall(checkInterfacesInside(*dm, scene, faceSets));
  PetscCall(checkInterfaceJunctions(*dm, scene, faceSets, faces));

  // The sequence of DMPlexCreateHybridMesh, with faces marked explicitly (finding them from
  // vertices picks wrong faces in thin parts; see docs/petsc.md).
  DM sub;
  PetscCall(DMPlexCreateSubmesh(*dm, faces, 1, PETSC_TRUE, &sub));
  PetscCall(DMPlexOrient(sub));
  DMLabel subpointMap, split, buried;
  PetscCall(DMPlexGetSubpointMap(sub, &subpointMap));
  PetscCall(DMLabelDuplicate(subpointMap, &split));
  PetscCall(DMLabelClearStratum(split, dim));
  PetscCall(DMLabelCreate(PETSC_COMM_SELF, "buried tips", &buried));
  PetscCall(markBuriedTips(*dm, faces, buried));
  PetscInt tips = 0;
  PetscCall(DMLabelGetStratumSize(buried, 1, &tips));
  // PETSc 3.18 dereferences an empty buried-tip stratum: pass no label when there are no tips.
  PetscCall(DMPlexLabelCohesiveComplete(*dm, split, tips ? buried : nullptr, 1, PETSC_FALSE, sub));
  DM dmSplit;
  PetscCall(DMPlexConstructCohesiveCells(*dm, split, nullptr, &dmSplit));
  {
    DM cdm;
    DMLabel ctLabel;
    PetscCall(DMGetCoordinateDM(dmSplit, &cdm));
    PetscCall(DMPlexGetCellTypeLabel(dmSplit, &ctLabel));
    PetscCall(DMSetLabel(cdm, ctLabel));
  }
  PetscCall(DMLabelDestroy(&split));
  PetscCall(DMLabelDestroy(&buried));
  PetscCall(DMLabelDestroy(&faces));
  PetscCall(DMDestroy(&sub));
  PetscCall(keepCurvedNodes(*dm, dmSplit));
  PetscCall(DMDestroy(dm));
  *dm = dmSplit;
  PetscCall(PetscObjectSetName((PetscObject)*dm, "mesh"));

  // Labels of the cohesive cells: interface, surface, side 1 and normal orientation.
  DMLabel cellSets, iface, surface, side, normal;
  PetscCall(DMGetLabel(*dm, "Cell Sets", &cellSets));
  PetscCall(DMGetLabel(*dm, "Face Sets", &faceSets));
  for (const char *name :
       {kInterfaceLabel, kInterfaceSurfaceLabel, kInterfaceSideLabel, kInterfaceNormalLabel})
    PetscCall(DMCreateLabel(*dm, name));
  PetscCall(DMGetLabel(*dm, kInterfaceLabel, &iface));
  PetscCall(DMGetLabel(*dm, kInterfaceSurfaceLabel, &surface));
  PetscCall(DMGetLabel(*dm, kInterfaceSideLabel, &side));
  PetscCall(DMGetLabel(*dm, kInterfaceNormalLabel, &normal));
  PetscInt cStart, cEnd;
  PetscCall(DMPlexGetHeightStratum(*dm, 0, &cStart, &cEnd));
  std::string error;
  for (PetscInt c = cStart; c < cEnd && error.empty(); ++c) {
    DMPolytopeType t;
    PetscCall(DMPlexGetCellType(*dm, c, &t));
    if (!isCohesive(t)) continue;
    const PetscInt *cone;
    PetscCall(DMPlexGetCone(*dm, c, &cone));
    PetscInt tag = -1;
    PetscCall(DMLabelGetValue(faceSets, cone[0], &tag));
    if (tag < 0) PetscCall(DMLabelGetValue(faceSets, cone[1], &tag));
    const auto found = surfaceOfTag.find((int)tag);
    if (found == surfaceOfTag.end()) {
      error = "a cohesive cell has no interface face group (internal error in the split)";
      break;
    }
    const Interface &in = scene.interfaces[found->second.first];
    PetscInt neighbour[2], region[2] = {-1, -1};
    for (int s = 0; s < 2; ++s) {
      PetscCall(bulkNeighbour(*dm, cone[s], &neighbour[s]));
      if (neighbour[s] >= 0) PetscCall(DMLabelGetValue(cellSets, neighbour[s], &region[s]));
    }
    int sideFace = region[0] == in.side1_tag ? 0 : region[1] == in.side1_tag ? 1 : -1;
    if (sideFace < 0) {
      auto regionName = [&](PetscInt tag) -> std::string {
        if (tag < 0) return "no region";
        const int r = scene.regionIndexOfTag((int)tag);
        return r >= 0 ? "'" + scene.regions[r].name + "'"
                      : "cells of tag " + std::to_string(tag) + " (not in -regions)";
      };
      std::vector<double> fx;
      PetscCall(closureCoordinates(*dm, cone[0], fx));
      double where[3];
      centroid(fx, (int)dim, where);
      std::ostringstream msg;
      msg << "interface '" << in.name << "': its side 1 (-interface_" << in.name << "_side1 "
          << in.side1 << ") does not border its face group '" << in.surfaces[found->second.second]
          << "' near (" << where[0] << ", " << where[1] << ", " << where[2]
          << "), which lies between " << regionName(region[0]) << " and " << regionName(region[1])
          << ". Side 1 is one region that borders every face of the "
          << "interface: where a fault crosses layers, give it one interface per layer (one face "
          << "group each, meeting end to end), each with a region of its own layer as side 1 "
          << "(docs/interface_parameters.md, \"Interfaces in layered ground\")";
      error = msg.str();
      break;
    }
    // Orientation of cone[0]'s natural normal relative to side 1 -> side 2.
    std::vector<double> fx, cx;
    PetscCall(closureCoordinates(*dm, cone[0], fx));
    PetscCall(closureCoordinates(*dm, neighbour[sideFace], cx));
    double n[3], fc[3], cc[3];
    faceNormal(fx.data(), (int)fx.size() / (int)dim, (int)dim, n);
    centroid(fx, (int)dim, fc);
    centroid(cx, (int)dim, cc);
    double dot = 0.0;
    for (int d = 0; d < dim; ++d)
      dot += n[d] * (fc[d] - cc[d]);
    PetscCall(DMLabelSetValue(iface, c, found->second.first + 1));
    PetscCall(DMLabelSetValue(surface, c, found->second.second + 1));
    PetscCall(DMLabelSetValue(side, c, sideFace + 1));
    PetscCall(DMLabelSetValue(normal, c, dot > 0.0 ? 1 : 2));
  }
  PetscCall(checkOnAllRanks(comm, error));
  PetscFunctionReturn(0);
}

} // namespace poroseam
