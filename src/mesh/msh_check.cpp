// The checker of a Gmsh .msh file (MSH 2.2 and 4.1, ASCII and binary) that runs before PETSc
// reads it: sections, counts, node tags, element types and their nodes, one line per error
// (msh_check.hpp). Gmsh's element types are in msh_element_types.cpp, the bytes in
// msh_cursor.hpp, the geometry in msh_geometry.cpp.
#include "poroseam/msh_check.hpp"

#include "poroseam/msh_cursor.hpp"
#include "poroseam/msh_element_types.hpp"
#include "poroseam/msh_geometry.hpp"

#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <sys/stat.h>
#include <unordered_set>

namespace poroseam {
namespace {

struct Failure {
  std::string what;
};

using msh::Cursor;
using msh::linearType;
using msh::nodesOfType;
using msh::typeName;

class MshChecker {
public:
  MshChecker(const std::string &data, std::vector<PhysicalName> &names, MshSummary &s)
      : c_(data), names_(names), s_(s)
  {
  }

  void run()
  {
    c_.skipSpace();
    if (c_.atEnd()) fail("the file is empty");
    if (c_.token() != "$MeshFormat")
      fail("not a Gmsh mesh: it does not start with $MeshFormat", false, 0);
    readFormat();
    bool physical = false, entities = false, nodes = false, elements = false;
    while (true) {
      const std::string section = c_.token();
      if (section.empty()) break;
      if (section.size() < 2 || section[0] != '$')
        fail("expected a section ($Nodes, $Elements, ...), found '" + printable(section) + "'");
      const std::string name = section.substr(1);
      c_.line(); // the header's line: binary data start on the next one
      if (name == "PhysicalNames") {
        if (nodes) fail("$PhysicalNames after $Nodes (Gmsh writes it before)");
        readPhysicalNames();
        physical = true;
      } else if (name == "Entities") {
        if (s_.version != 41) fail("$Entities in a MSH 2.2 file");
        if (nodes) fail("$Entities after $Nodes (Gmsh writes it before)");
        readEntities();
        entities = true;
      } else if (name == "Nodes") {
        if (nodes) fail("a second $Nodes section");
        if (s_.version == 41 && !entities)
          fail("$Nodes before $Entities (MSH 4.1 needs $Entities first)");
        readNodes();
        nodes = true;
      } else if (name == "Elements") {
        if (!nodes) fail("$Elements before $Nodes");
        if (elements) fail("a second $Elements section");
        readElements();
        elements = true;
      } else if (name.rfind("End", 0) == 0) {
        fail("'" + printable(section) + "' without its section");
      } else {
        // $Comments, $Periodic, $NodeData, ...: not ours to read; they must end.
        if (!c_.skipPast("$End" + name))
          fail("section $" + printable(name) + " has no $End" + printable(name) +
               " (the file is truncated)");
      }
    }
    if (!nodes) fail("no $Nodes section (the file is truncated, or not a mesh)", false, 0);
    if (!elements) fail("no $Elements section (the file is truncated, or not a mesh)", false, 0);
    if (s_.cells == 0) fail("no elements", false, 0);
    if (!physical)
      fail("no $PhysicalNames: name the regions and boundaries as Gmsh physical groups", false, 0);
    const std::string why = geometry_.finish(names_, s_.dim);
    if (!why.empty()) fail(why, false, 0);
  }

private:
  [[noreturn]] void fail(const std::string &what, bool binary_part = false, int show_where = 1)
  {
    throw Failure{what + (show_where ? " (" + c_.where(binary_part) + ")" : "")};
  }

  static std::string printable(const std::string &s)
  {
    std::string out;
    for (unsigned char ch : s.substr(0, 40))
      out += std::isprint(ch) ? (char)ch : '?';
    return out + (s.size() > 40 ? "..." : "");
  }

  void expectEnd(const std::string &name)
  {
    const std::string t = c_.token();
    if (t != "$End" + name)
      fail(t.empty() ? "the file ends inside $" + name + " (truncated?)"
                     : "expected $End" + name + ", found '" + printable(t) + "' (a count in $" +
                           name + " does not match its entries)");
  }

  long long integer(const char *what, long long min = 0)
  {
    const std::string t = c_.token();
    if (t.empty()) fail(std::string("the file ends where ") + what + " was expected (truncated?)");
    if (t[0] == '$')
      fail("'" + printable(t) + "' where " + what + " was expected: the section ends before " +
           "its count of entries (truncated, or a wrong count)");
    errno = 0;
    char *end = nullptr;
    const long long v = std::strtoll(t.c_str(), &end, 10);
    if (errno != 0 || !end || *end != '\0')
      fail(std::string("expected ") + what + " (an integer), found '" + printable(t) + "'");
    if (v < min)
      fail(std::string(what) + " " + std::to_string(v) + " must be >= " + std::to_string(min));
    return v;
  }

  double real(const char *what)
  {
    const std::string t = c_.token();
    if (t.empty()) fail(std::string("the file ends where ") + what + " was expected (truncated?)");
    if (t[0] == '$')
      fail("'" + printable(t) + "' where " + what + " was expected: the section ends before " +
           "its count of entries (truncated, or a wrong count)");
    char *end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if (!end || *end != '\0')
      fail(std::string("expected ") + what + " (a number), found '" + printable(t) + "'");
    if (!std::isfinite(v))
      fail(std::string(what) + " is " + printable(t) + ", not a finite number");
    return v;
  }

  template <class T> T bin(const char *what)
  {
    T v;
    if (!c_.raw(&v, sizeof v))
      fail(std::string("the file ends where ") + what + " was expected (truncated?)", true);
    if (swap_) {
      unsigned char *b = reinterpret_cast<unsigned char *>(&v);
      for (size_t i = 0; i < sizeof v / 2; ++i)
        std::swap(b[i], b[sizeof v - 1 - i]);
    }
    return v;
  }

  /// A count or tag: int in MSH 2.2 binary and 4.1 block headers, size_t elsewhere in 4.1.
  long long binSize(const char *what) { return (long long)bin<uint64_t>(what); }

  void readFormat()
  {
    const double version = real("the format version");
    const long long type = integer("the file type (0 ASCII, 1 binary)");
    const long long size = integer("the data size");
    s_.version = (int)std::lround(version * 10);
    if (s_.version != 22 && s_.version != 41) {
      std::ostringstream v;
      v << version;
      fail("MSH format " + v.str() +
           " is not supported: write MSH 2.2 or 4.1 (gmsh -format msh22 or msh41)");
    }
    if (type != 0 && type != 1) fail("file type " + std::to_string(type) + ": expected 0 or 1");
    if (size != 8) fail("data size " + std::to_string(size) + ": expected 8");
    s_.binary = type == 1;
    c_.line(); // end of the format line
    if (s_.binary) {
      const int one = bin<int32_t>("the binary endianness mark");
      if (one != 1) {
        int32_t swapped = one;
        unsigned char *b = reinterpret_cast<unsigned char *>(&swapped);
        std::swap(b[0], b[3]);
        std::swap(b[1], b[2]);
        if (swapped != 1) fail("bad binary endianness mark (expected the integer 1)", true);
        swap_ = true;
      }
    }
    expectEnd("MeshFormat");
  }

  void readPhysicalNames()
  {
    const long long count = integer("the number of physical names");
    c_.line();
    for (long long i = 0; i < count; ++i) {
      const std::string text = c_.line();
      PhysicalName n;
      std::istringstream fields(text);
      const auto a = text.find('"'), b = text.rfind('"');
      if (!(fields >> n.dim >> n.tag) || a == std::string::npos || b <= a || n.dim < 0 ||
          n.dim > 3) {
        if (c_.atEnd() && text.empty()) fail("the file ends inside $PhysicalNames (truncated?)");
        fail("bad $PhysicalNames entry '" + printable(text) + "': expected dim tag \"name\"");
      }
      n.name = text.substr(a + 1, b - a - 1);
      names_.push_back(n);
    }
    expectEnd("PhysicalNames");
  }

  void readEntities()
  {
    long long count[4];
    for (int d = 0; d < 4; ++d)
      count[d] = s_.binary ? binSize("an entity count") : integer("an entity count");
    for (int d = 0; d < 4; ++d)
      for (long long i = 0; i < count[d]; ++i) {
        const long long tag =
            s_.binary ? bin<int32_t>("an entity tag") : integer("an entity tag", LLONG_MIN);
        for (int k = 0; k < (d == 0 ? 3 : 6); ++k)
          if (s_.binary) {
            const double x = bin<double>("an entity coordinate");
            if (!std::isfinite(x)) fail("an entity coordinate is not finite", true);
          } else {
            real("an entity coordinate");
          }
        const long long physical =
            s_.binary ? binSize("a physical tag count") : integer("a physical tag count");
        if (physical > 16)
          fail("entity " + std::to_string(tag) + " has " + std::to_string(physical) +
                   " physical tags (at most 16)",
               s_.binary);
        std::vector<long long> &groups = physicals_[d][tag];
        for (long long k = 0; k < physical; ++k)
          groups.push_back(s_.binary ? bin<int32_t>("a physical tag")
                                     : integer("a physical tag", LLONG_MIN));
        if (d > 0) {
          const long long bounding =
              s_.binary ? binSize("a bounding entity count") : integer("a bounding entity count");
          if (bounding < 0 || bounding > 1000000) fail("bad bounding entity count", s_.binary);
          for (long long k = 0; k < bounding; ++k)
            s_.binary ? (void)bin<int32_t>("a bounding entity")
                      : (void)integer("a bounding entity", LLONG_MIN);
        }
        entities_[d].insert(tag);
      }
    expectEnd("Entities");
  }

  /// A node tag before its coordinates: >= 1, and not absurdly large (PETSc's reader sizes
  /// arrays by the largest tag: 2e9 in a file of 4 nodes takes gigabytes, then aborts).
  void checkNodeTag(long long tag, long long count, bool binary_part)
  {
    if (tag < 1) fail("node tag " + std::to_string(tag) + " must be >= 1", binary_part);
    if (tag > MshGeometry::maxNodeTag(count))
      fail("node tag " + std::to_string(tag) + " is far beyond the file's " +
               std::to_string(count) + " nodes (at most " +
               std::to_string(MshGeometry::maxNodeTag(count)) +
               "): PETSc's reader sizes its arrays by the largest tag; number the nodes from 1",
           binary_part);
    if (geometry_.has(tag)) fail("node " + std::to_string(tag) + " is defined twice", binary_part);
  }

  void addNode(long long tag, const double x[3], bool binary_part)
  {
    if (!geometry_.node(tag, x[0], x[1], x[2]))
      fail("node " + std::to_string(tag) + " is defined twice", binary_part);
  }

  void readNodes()
  {
    if (s_.version == 22) {
      const long long n = integer("the number of nodes");
      if (s_.binary) c_.line();
      for (long long i = 0; i < n; ++i) {
        double x[3];
        if (s_.binary) {
          const long long tag = bin<int32_t>("a node tag");
          checkNodeTag(tag, n, true);
          for (int k = 0; k < 3; ++k)
            if (!std::isfinite(x[k] = bin<double>("a node coordinate")))
              fail("a node coordinate is not finite", true);
          addNode(tag, x, true);
        } else {
          const long long tag = integer("a node tag", LLONG_MIN);
          checkNodeTag(tag, n, false);
          for (int k = 0; k < 3; ++k)
            x[k] = real("a node coordinate");
          addNode(tag, x, false);
        }
      }
      s_.nodes = n;
      expectEnd("Nodes");
      return;
    }
    long long blocks, total, min_tag, max_tag;
    if (s_.binary) {
      blocks = binSize("the number of node blocks");
      total = binSize("the number of nodes");
      min_tag = binSize("the smallest node tag");
      max_tag = binSize("the largest node tag");
    } else {
      blocks = integer("the number of node blocks");
      total = integer("the number of nodes");
      min_tag = integer("the smallest node tag");
      max_tag = integer("the largest node tag");
    }
    if (total > 0 && (max_tag < min_tag || max_tag - min_tag > 100 * total + 1000000))
      fail("node tag range " + std::to_string(min_tag) + ".." + std::to_string(max_tag) +
               " does not fit " + std::to_string(total) + " nodes",
           s_.binary);
    long long seen = 0;
    for (long long b = 0; b < blocks; ++b) {
      long long dim, entity, parametric, n;
      if (s_.binary) {
        dim = bin<int32_t>("a node block's dimension");
        entity = bin<int32_t>("a node block's entity");
        parametric = bin<int32_t>("a node block's parametric flag");
        n = binSize("a node block's size");
      } else {
        dim = integer("a node block's dimension");
        entity = integer("a node block's entity", LLONG_MIN);
        parametric = integer("a node block's parametric flag");
        n = integer("a node block's size");
      }
      if (dim > 3) fail("node block of dimension " + std::to_string(dim), s_.binary);
      if (!entities_[dim].count(entity))
        fail("node block names entity " + std::to_string(entity) + " of dimension " +
                 std::to_string(dim) + ", which is not in $Entities",
             s_.binary);
      if (parametric) fail("parametric node coordinates are not supported", s_.binary);
      if (n < 0 || seen + n > total)
        fail("the node blocks hold more than the " + std::to_string(total) + " nodes declared",
             s_.binary);
      seen += n;
      std::vector<long long> tags((size_t)n);
      for (long long i = 0; i < n; ++i) {
        const long long tag = s_.binary ? binSize("a node tag") : integer("a node tag", LLONG_MIN);
        if (tag < min_tag || tag > max_tag)
          fail("node tag " + std::to_string(tag) + " outside the declared range " +
                   std::to_string(min_tag) + ".." + std::to_string(max_tag),
               s_.binary);
        checkNodeTag(tag, total, s_.binary);
        tags[i] = tag;
      }
      for (long long i = 0; i < n; ++i) {
        double x[3];
        for (int k = 0; k < 3; ++k)
          if (s_.binary) {
            if (!std::isfinite(x[k] = bin<double>("a node coordinate")))
              fail("a node coordinate is not finite", true);
          } else {
            x[k] = real("a node coordinate");
          }
        addNode(tags[i], x, s_.binary);
      }
    }
    if (seen != total)
      fail("the node blocks hold " + std::to_string(seen) + " nodes, " + std::to_string(total) +
               " declared",
           s_.binary);
    s_.nodes = total;
    expectEnd("Nodes");
  }

  /// A point or line element of a physical group: kept for the supports (MshSummary).
  void support(long long type, long long physical, const std::vector<long long> &nodes)
  {
    if (type == 15) s_.points.push_back({physical, geometry_.coordinates(nodes[0])});
    if (type != 1) return;
    const auto &a = geometry_.coordinates(nodes[0]), &b = geometry_.coordinates(nodes[1]);
    s_.lines.push_back({physical, {a[0], a[1], a[2], b[0], b[1], b[2]}});
  }

  void element(long long tag, long long type, const std::vector<long long> &nodes,
               long long physical, bool binary)
  {
    for (long long node : nodes)
      if (!geometry_.has(node))
        fail("element " + std::to_string(tag) + " refers to node " + std::to_string(node) +
                 ", which is not in $Nodes",
             binary);
    // A second-order element: its corners are checked as the linear element (the cell's
    // shape), its order noted; one file holds one order (PETSc reads one coordinate degree).
    const long linear = linearType(type);
    const int order = linear == type ? 1 : 2;
    if (type != 15) {
      if (s_.order == 0) s_.order = order;
      if (s_.order != order)
        fail("element " + std::to_string(tag) + " is of order " + std::to_string(order) +
                 " and an earlier one of order " + std::to_string(s_.order) +
                 ": give one order for the whole mesh (gmsh -order 1 or 2)",
             binary);
    }
    int corners_dim = 0;
    corners_.assign(nodes.begin(), nodes.begin() + nodesOfType(linear, &corners_dim));
    const std::string why = geometry_.element(tag, linear, corners_, physical);
    if (!why.empty()) fail(why, binary);
    if (physical >= 0) support(linear, physical, corners_);
    int dim = 0;
    nodesOfType(type, &dim);
    if (dim > s_.dim) s_.dim = dim, s_.cells = 0;
    if (dim == s_.dim) ++s_.cells;
  }

  int checkedType(long long type, bool binary)
  {
    int dim = 0;
    const int n = nodesOfType(type, &dim);
    if (n < 0)
      fail("element type " + std::to_string(type) + " (" + typeName(type) +
               ") is not supported: poroseam needs points, lines, triangles, "
               "quadrangles, tetrahedra or hexahedra, linear (gmsh -order 1) or complete "
               "second-order (gmsh -order 2, for -mesh_geometry_order 2)",
           binary);
    return n;
  }

  void readElements()
  {
    std::vector<long long> nodes;
    if (s_.version == 22) {
      const long long total = integer("the number of elements");
      if (!s_.binary) {
        for (long long i = 0; i < total; ++i) {
          const long long tag = integer("an element tag");
          const long long type = integer("an element type");
          const int n = checkedType(type, false);
          const long long ntags = integer("an element's number of tags");
          if (ntags > 16) fail("element " + std::to_string(tag) + " has more than 16 tags");
          long long physical = -1; // MSH 2.2: the first tag is the physical group
          for (long long k = 0; k < ntags; ++k) {
            const long long v = integer("an element tag value", LLONG_MIN);
            if (k == 0) physical = v;
          }
          nodes.resize(n);
          for (int k = 0; k < n; ++k)
            nodes[k] = integer("an element's node", LLONG_MIN);
          element(tag, type, nodes, physical, false);
        }
      } else {
        c_.line();
        long long seen = 0;
        while (seen < total) {
          const long long type = bin<int32_t>("an element group's type");
          const long long count = bin<int32_t>("an element group's size");
          const long long ntags = bin<int32_t>("an element group's number of tags");
          const int n = checkedType(type, true);
          if (count < 1 || seen + count > total)
            fail("element group of " + std::to_string(count) + " elements does not fit the " +
                     std::to_string(total) + " declared",
                 true);
          if (ntags < 0 || ntags > 16) fail("element group with more than 16 tags", true);
          seen += count;
          nodes.resize(n);
          for (long long i = 0; i < count; ++i) {
            const long long tag = bin<int32_t>("an element tag");
            long long physical = -1;
            for (long long k = 0; k < ntags; ++k) {
              const long long v = bin<int32_t>("an element tag value");
              if (k == 0) physical = v;
            }
            for (int k = 0; k < n; ++k)
              nodes[k] = bin<int32_t>("an element's node");
            element(tag, type, nodes, physical, true);
          }
        }
      }
      expectEnd("Elements");
      return;
    }
    long long blocks, total;
    if (s_.binary) {
      blocks = binSize("the number of element blocks");
      total = binSize("the number of elements");
      binSize("the smallest element tag");
      binSize("the largest element tag");
    } else {
      blocks = integer("the number of element blocks");
      total = integer("the number of elements");
      integer("the smallest element tag");
      integer("the largest element tag");
    }
    long long seen = 0;
    for (long long b = 0; b < blocks; ++b) {
      long long dim, entity, type, count;
      if (s_.binary) {
        dim = bin<int32_t>("an element block's dimension");
        entity = bin<int32_t>("an element block's entity");
        type = bin<int32_t>("an element block's type");
        count = binSize("an element block's size");
      } else {
        dim = integer("an element block's dimension");
        entity = integer("an element block's entity", LLONG_MIN);
        type = integer("an element block's type");
        count = integer("an element block's size");
      }
      const int n = checkedType(type, s_.binary);
      int type_dim = 0;
      nodesOfType(type, &type_dim);
      if (dim != type_dim)
        fail("element block of dimension " + std::to_string(dim) + " holds elements of type " +
                 std::to_string(type) + " (dimension " + std::to_string(type_dim) + ")",
             s_.binary);
      if (!entities_[dim].count(entity))
        fail("element block names entity " + std::to_string(entity) + " of dimension " +
                 std::to_string(dim) + ", which is not in $Entities",
             s_.binary);
      if (count < 0 || seen + count > total)
        fail("the element blocks hold more than the " + std::to_string(total) +
                 " elements declared",
             s_.binary);
      seen += count;
      nodes.resize(n);
      // MSH 4.1: the physical groups of an element are those of its entity
      const auto groups = physicals_[dim].find(entity);
      const std::vector<long long> none;
      const std::vector<long long> &physical =
          groups == physicals_[dim].end() ? none : groups->second;
      for (long long i = 0; i < count; ++i) {
        const long long tag = s_.binary ? binSize("an element tag") : integer("an element tag");
        for (int k = 0; k < n; ++k)
          nodes[k] =
              s_.binary ? binSize("an element's node") : integer("an element's node", LLONG_MIN);
        element(tag, type, nodes, physical.empty() ? -1 : physical[0], s_.binary);
        for (size_t k = 1; k < physical.size(); ++k) {
          geometry_.usePhysical((int)dim, physical[k]); // the entity's other groups
          support(linearType(type), physical[k], nodes);
        }
      }
    }
    if (seen != total)
      fail("the element blocks hold " + std::to_string(seen) + " elements, " +
               std::to_string(total) + " declared",
           s_.binary);
    expectEnd("Elements");
  }

  Cursor c_;
  std::vector<PhysicalName> &names_;
  MshSummary &s_;
  bool swap_ = false;
  std::set<long long> entities_[4];
  std::map<long long, std::vector<long long>> physicals_[4]; // entity -> its physical tags
  MshGeometry geometry_;
  std::vector<long long> corners_;
};

} // namespace

std::string checkGmshFile(const std::string &path, std::vector<PhysicalName> &names,
                          MshSummary &summary)
{
  const std::string file = "mesh file '" + path + "' (option -mesh)";
  struct stat st;
  if (stat(path.c_str(), &st) != 0) return file + " does not exist";
  if (S_ISDIR(st.st_mode)) return file + " is a directory: expected a Gmsh .msh or .geo file";
  if (!S_ISREG(st.st_mode)) return file + " is not a regular file";
  std::ifstream in(path, std::ios::binary);
  if (!in) return file + ": cannot be read (" + std::strerror(errno) + ")";
  std::string data;
  data.resize((size_t)st.st_size);
  if (st.st_size > 0 && !in.read(&data[0], st.st_size)) return file + ": cannot be read";
  names.clear();
  summary = MshSummary{};
  try {
    MshChecker(data, names, summary).run();
  } catch (const Failure &f) {
    names.clear();
    return file + ": " + f.what;
  } catch (const std::bad_alloc &) {
    names.clear();
    return file + ": too large to check in memory";
  }
  return "";
}

} // namespace poroseam
