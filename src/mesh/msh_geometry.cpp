#include "poroseam/msh_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace poroseam {
namespace {

/// Relative tolerance: two nodes closer than this times the mesh's diameter coincide; a cell
/// whose size is below it times its longest edge (to the power of its dimension) is degenerate.
constexpr double kRelative = 1e-10;

using Vec3 = std::array<double, 3>;

Vec3 sub(const Vec3 &a, const Vec3 &b)
{
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
Vec3 cross(const Vec3 &a, const Vec3 &b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec3 &a, const Vec3 &b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
double norm(const Vec3 &a)
{
  return std::sqrt(dot(a, a));
}

std::string point(const Vec3 &x)
{
  std::ostringstream s;
  s << "(" << x[0] << ", " << x[1] << ", " << x[2] << ")";
  return s.str();
}

} // namespace

bool MshGeometry::node(long long tag, double x, double y, double z)
{
  if (!index_.emplace(tag, x_.size()).second) return false;
  const double c[3] = {x, y, z};
  for (int k = 0; k < 3; ++k) {
    lo_[k] = x_.empty() ? c[k] : std::min(lo_[k], c[k]);
    hi_[k] = x_.empty() ? c[k] : std::max(hi_[k], c[k]);
  }
  x_.push_back({x, y, z});
  tags_.push_back(tag);
  diameter_ = -1;
  return true;
}

double MshGeometry::diameter() const
{
  if (diameter_ < 0)
    diameter_ =
        std::sqrt((hi_[0] - lo_[0]) * (hi_[0] - lo_[0]) + (hi_[1] - lo_[1]) * (hi_[1] - lo_[1]) +
                  (hi_[2] - lo_[2]) * (hi_[2] - lo_[2]));
  return diameter_;
}

std::string MshGeometry::element(long long tag, long long type, const std::vector<long long> &nodes,
                                 long long physical)
{
  std::vector<Vec3> p;
  for (long long n : nodes)
    p.push_back(x_[index_.at(n)]);
  int dim = type == 15 ? 0 : type == 1 ? 1 : (type == 2 || type == 3) ? 2 : 3;
  if (physical >= 0) used_.insert({dim, physical});
  if (dim > 0) { // kept (as node indices) for the check that faces are faces of cells
    types_.push_back((char)type);
    tags_of_elements_.push_back(tag);
    physical_of_elements_.push_back(physical);
    for (long long n : nodes)
      element_nodes_.push_back((unsigned)index_.at(n));
  }
  if (dim == 0) return "";
  const char *name = type == 1   ? "line"
                     : type == 2 ? "triangle"
                     : type == 3 ? "quadrangle"
                     : type == 4 ? "tetrahedron"
                                 : "hexahedron";
  // the longest edge between consecutive nodes (and across, for simplices): the cell's scale
  double h = 0;
  for (size_t a = 0; a < p.size(); ++a)
    for (size_t b = a + 1; b < p.size(); ++b)
      h = std::max(h, norm(sub(p[a], p[b])));
  // the messages are made only for a bad element (this runs for every element of the file)
  auto which = [&]() {
    std::ostringstream nodes_text;
    for (size_t a = 0; a < nodes.size(); ++a)
      nodes_text << (a ? " " : "") << nodes[a];
    return std::string(name) + " element " + std::to_string(tag) + " (nodes " + nodes_text.str() +
           ", near " + point(p[0]) + ")";
  };
  auto degenerate = [&]() {
    return which() + " is degenerate: its " +
           (dim == 1   ? "length"
            : dim == 2 ? "area"
                       : "volume") +
           " is zero (coincident or aligned nodes); fix the mesh";
  };
  if (h <= kRelative * diameter()) return degenerate();
  const double scale = std::pow(h, dim), tol = kRelative * scale;
  for (size_t a = 0; a < p.size(); ++a) // two of its nodes at one place (or the same node twice)
    for (size_t b = a + 1; b < p.size(); ++b)
      if (norm(sub(p[a], p[b])) <= kRelative * h) return degenerate();
  if (type == 2) {
    if (0.5 * norm(cross(sub(p[1], p[0]), sub(p[2], p[0]))) <= tol) return degenerate();
  } else if (type == 4) {
    if (std::fabs(dot(cross(sub(p[1], p[0]), sub(p[2], p[0])), sub(p[3], p[0]))) / 6 <= tol)
      return degenerate();
  } else if (type == 3) {
    // The bilinear map is one-to-one only when the Jacobian keeps its sign at all four
    // corners: a folded (bow-tie) or non-convex quadrangle has corners of both signs.
    Vec3 c[4];
    int largest = 0;
    for (int i = 0; i < 4; ++i) {
      c[i] = cross(sub(p[(i + 1) % 4], p[i]), sub(p[(i + 3) % 4], p[i]));
      if (norm(c[i]) > norm(c[largest])) largest = i;
    }
    const Vec3 ref = c[largest];
    if (norm(ref) <= tol) return degenerate();
    for (int i = 0; i < 4; ++i)
      if (dot(c[i], ref) / norm(ref) < -tol)
        return which() + " is folded (self-intersecting) or not convex: its corner at node " +
               std::to_string(nodes[i]) +
               " turns the other way from the others (the Jacobian changes sign inside it); " +
               "fix the node order or the node positions";
    for (int i = 0; i < 4; ++i) // three aligned nodes: a corner with a zero Jacobian
      if (dot(c[i], ref) / norm(ref) <= tol) return degenerate();
  } else if (type == 5) {
    // Gmsh's order: 0-1-2-3 bottom, 4-5-6-7 top; vertex (a, b, c) of the unit cube.
    static const int at[2][2][2] = {{{0, 4}, {3, 7}}, {{1, 5}, {2, 6}}};
    double positive = 0, negative = 0;
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b)
        for (int cc = 0; cc < 2; ++cc) {
          const Vec3 dx = sub(p[at[1][b][cc]], p[at[0][b][cc]]);
          const Vec3 dy = sub(p[at[a][1][cc]], p[at[a][0][cc]]);
          const Vec3 dz = sub(p[at[a][b][1]], p[at[a][b][0]]);
          const double j = dot(cross(dx, dy), dz);
          if (j > tol) positive += 1;
          if (j < -tol) negative += 1;
        }
    if (positive == 0 && negative == 0) return degenerate();
    if (positive > 0 && negative > 0)
      return which() + " is folded (self-intersecting) or not convex: the Jacobian at its " +
             "corners changes sign; fix the node order or the node positions";
    if (positive + negative < 8) return degenerate();
  } else if (type == 1) {
    // h is its length, checked above
  }
  return "";
}

std::string MshGeometry::finish(const std::vector<PhysicalName> &names, int mesh_dim) const
{
  for (const auto &n : names)
    if (!used_.count({n.dim, (long long)n.tag}))
      return "physical group '" + n.name + "' (dimension " + std::to_string(n.dim) + ", tag " +
             std::to_string(n.tag) + ") has no elements: a group that names nothing (a " +
             "geometry not meshed, or a wrong tag); remove it from $PhysicalNames or give " +
             "it elements";
  const double tol = kRelative * diameter();
  if (mesh_dim == 2)
    for (size_t i = 0; i < x_.size(); ++i)
      if (std::fabs(x_[i][2]) > tol)
        return "node " + std::to_string(tags_[i]) + " of this 2D mesh has z = " +
               [&] {
                 std::ostringstream s;
                 s << x_[i][2];
                 return s.str();
               }() +
               ": a 2D mesh must lie in the plane z = 0 (poroseam uses x and y only and " +
               "would drop z)";
  // Coincident nodes: a hash of cells of size tol, each node compared with its 27 cells.
  if (tol > 0) {
    struct Key {
      long long i, j, k;
      bool operator==(const Key &o) const { return i == o.i && j == o.j && k == o.k; }
    };
    struct Hash {
      size_t operator()(const Key &k) const
      {
        return std::hash<long long>()(k.i * 73856093LL ^ k.j * 19349663LL ^ k.k * 83492791LL);
      }
    };
    std::unordered_multimap<Key, size_t, Hash> cells; // ~40 bytes a node
    auto keyOf = [&](const Vec3 &x) {
      return Key{(long long)std::floor((x[0] - lo_[0]) / tol),
                 (long long)std::floor((x[1] - lo_[1]) / tol),
                 (long long)std::floor((x[2] - lo_[2]) / tol)};
    };
    // with tol = 1e-10 diameter the cell indices reach 1e10: they fit a long long
    for (size_t n = 0; n < x_.size(); ++n) {
      const Key k = keyOf(x_[n]);
      for (long long di = -1; di <= 1; ++di)
        for (long long dj = -1; dj <= 1; ++dj)
          for (long long dk = -1; dk <= 1; ++dk) {
            const auto range = cells.equal_range(Key{k.i + di, k.j + dj, k.k + dk});
            for (auto it = range.first; it != range.second; ++it)
              if (const size_t m = it->second; norm(sub(x_[m], x_[n])) <= tol)
                return "nodes " + std::to_string(tags_[m]) + " and " + std::to_string(tags_[n]) +
                       " coincide at " + point(x_[n]) +
                       ": the cells on either side would not be joined; merge them (gmsh " +
                       "Coherence) or remove the duplicate";
          }
      cells.emplace(k, n);
    }
  }
  return checkFaces(names, mesh_dim);
}

std::string MshGeometry::checkFaces(const std::vector<PhysicalName> &names, int mesh_dim) const
{
  // Every element of dimension mesh_dim - 1 (a boundary or interface face) must be a face of
  // a cell: PETSc's reader finds its DMPlex face by joining its vertices, and a line across a
  // quadrangle's diagonal labels the cell itself, one between unrelated nodes stops the reader.
  if (mesh_dim < 2) return "";
  struct KeyHash {
    size_t operator()(const std::vector<unsigned> &k) const
    {
      size_t h = 0;
      for (unsigned v : k)
        h = h * 1000003u ^ v;
      return h;
    }
  };
  std::unordered_map<std::vector<unsigned>, size_t, KeyHash> faces; // sorted nodes -> element
  std::vector<size_t> offset(types_.size() + 1, 0);
  for (size_t e = 0; e < types_.size(); ++e)
    offset[e + 1] = offset[e] + nodesOf(types_[e]);
  for (size_t e = 0; e < types_.size(); ++e)
    if (dimOf(types_[e]) == mesh_dim - 1) {
      std::vector<unsigned> key(element_nodes_.begin() + offset[e],
                                element_nodes_.begin() + offset[e + 1]);
      std::sort(key.begin(), key.end());
      faces.emplace(key, e);
    }
  if (faces.empty()) return "";
  // the faces of each linear cell type, as local node numbers (Gmsh's orders)
  static const std::vector<std::vector<int>> tri = {{0, 1}, {1, 2}, {2, 0}},
                                             quad = {{0, 1}, {1, 2}, {2, 3}, {3, 0}},
                                             tet = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}},
                                             hex = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                    {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  std::vector<char> found(types_.size(), 0);
  std::vector<unsigned> key;
  for (size_t e = 0; e < types_.size(); ++e) {
    if (dimOf(types_[e]) != mesh_dim) continue;
    const auto &local = types_[e] == 2 ? tri : types_[e] == 3 ? quad : types_[e] == 4 ? tet : hex;
    for (const auto &f : local) {
      key.clear();
      for (int a : f)
        key.push_back(element_nodes_[offset[e] + a]);
      std::sort(key.begin(), key.end());
      const auto hit = faces.find(key);
      if (hit != faces.end()) found[hit->second] = 1;
    }
  }
  for (size_t e = 0; e < types_.size(); ++e)
    if (dimOf(types_[e]) == mesh_dim - 1 && !found[e]) {
      std::string group = "no physical group";
      for (const auto &n : names)
        if (n.dim == mesh_dim - 1 && n.tag == physical_of_elements_[e])
          group = "physical group '" + n.name + "'";
      std::ostringstream nodes;
      for (size_t k = offset[e]; k < offset[e + 1]; ++k)
        nodes << (k > offset[e] ? " " : "") << tags_[element_nodes_[k]];
      return std::string(mesh_dim == 2 ? "line" : "surface") + " element " +
             std::to_string(tags_of_elements_[e]) + " (nodes " + nodes.str() + ", " + group +
             ", near " + point(x_[element_nodes_[offset[e]]]) + ") is not an " +
             (mesh_dim == 2 ? "edge" : "face") + " of any cell of the mesh: a boundary or " +
             "interface must follow the cells' edges (embed the curve or surface in the " +
             "geometry before meshing)";
    }
  return "";
}

} // namespace poroseam
