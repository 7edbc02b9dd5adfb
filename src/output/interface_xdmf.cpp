// The XDMF index of interfaces.h5 (interface_cells.xmf, interface_points.xmf): the
// attributes the HDF5 file holds, per grid and time, rewritten by rank 0 after every write().
// Apart from interface_datasets.cpp, which writes the datasets this names.
#include "interface_writer_impl.hpp"

#include <sstream>
#include <string>

namespace poroseam {

using namespace interface_output;

std::vector<Attribute> InterfaceWriter::Impl::attributes(bool cells) const
{
  const int t = dim - 1;
  const std::string g = cells ? "/cells/" : "/points/";
  std::vector<Attribute> a;
  // Per time.
  a.push_back({"gap_normal", g + "fields/gap_normal", 1, false, true});
  a.push_back({"opening", g + "fields/opening", 1, false, true});
  a.push_back({"slip", g + "fields/slip", t, false, true});
  a.push_back({"slip_vector", g + "fields/slip_vector", 3, false, true});
  a.push_back(
      {"contact_pressure_effective", g + "fields/contact_pressure_effective", 1, false, true});
  a.push_back({"shear_stress", g + "fields/shear_stress", t, false, true});
  a.push_back({"shear_traction", g + "fields/shear_traction", 3, false, true});
  a.push_back({"traction", g + "fields/traction", 3, false, true});
  a.push_back({"mobilised_friction", g + "fields/mobilised_friction", 1, false, true});
  a.push_back({"state", g + "fields/state", 1, true, true});
  if (flow) {
    a.push_back({"interface_pressure", g + "fields/interface_pressure", 1, false, true});
    a.push_back({"aperture", g + "fields/aperture", 1, false, true});
    a.push_back({"aperture_rate", g + "fields/aperture_rate", 1, false, true});
    a.push_back({"longitudinal_flux", g + "fields/longitudinal_flux", 3, false, true});
    a.push_back({"transversal_flux1", g + "fields/transversal_flux1", 1, false, true});
    a.push_back({"transversal_flux2", g + "fields/transversal_flux2", 1, false, true});
  }
  // On the nodes: the faces' displacements, to warp the interface with the bulk.
  a.push_back({"displacement_minus", g + "fields/displacement_minus", 3, false, true, true});
  a.push_back({"displacement_plus", g + "fields/displacement_plus", 3, false, true, true});
  // Constant.
  a.push_back({"interface", g + "interface", 1, true, false});
  a.push_back({"surface", g + "surface", 1, true, false});
  a.push_back({"part", g + "part", 1, true, false});
  a.push_back({"normal", g + "normal", 3, false, false});
  if (cells) {
    a.push_back({"area", g + "area", 1, false, false});
  } else {
    a.push_back({"cell", g + "cell", 1, true, false});
    a.push_back({"point", g + "point", 1, true, false});
    a.push_back({"weight", g + "weight", 1, false, false});
  }
  return a;
}

PetscErrorCode InterfaceWriter::Impl::writeXdmf()
{
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  for (int grid = 0; grid < 2; ++grid) {
    std::ostringstream x;
    if (rank == 0) {
      const bool have = mesh_written && num_cells > 0;
      const std::string geomType = dim == 3 ? "XYZ" : "XY";
      x << "<?xml version=\"1.0\" ?>\n"
        << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
        << "<Xdmf Version=\"3.0\">\n"
        << "  <Domain>\n";
      const bool cells = grid == 0;
      const std::string gname = cells ? "interface_cells" : "interface_points";
      const PetscInt n = cells ? num_cells : num_points;
      const std::string ns = std::to_string(n);
      x << "    <Grid Name=\"" << gname
        << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
      for (size_t s = 0; have && s < times.size(); ++s) {
        x << "      <Grid Name=\"" << gname << "\" GridType=\"Uniform\">\n"
          << "        <Time Value=\"" << xdmf::formatDouble(times[s]) << "\" />\n";
        if (cells) {
          const bool mixed = min_nodes != max_nodes;
          const char *type = dim == 2         ? "Polyline"
                             : mixed          ? "Mixed"
                             : max_nodes == 3 ? "Triangle"
                                              : "Quadrilateral";
          x << "        <Topology TopologyType=\"" << type << "\" NumberOfElements=\"" << ns
            << "\"";
          if (!mixed) x << " NodesPerElement=\"" << max_nodes << "\"";
          x << ">\n          "
            << xdmf::dataItem(mixed ? std::to_string(mixed_length) + " 1"
                                    : ns + " " + std::to_string(max_nodes),
                              true, h5name, "/cells/topology")
            << "\n        </Topology>\n"
            << "        <Geometry GeometryType=\"" << geomType << "\">\n          "
            << xdmf::dataItem(std::to_string(num_nodes) + " " + std::to_string(dim), false, h5name,
                              "/cells/geometry")
            << "\n        </Geometry>\n";
        } else {
          x << "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << ns
            << "\" NodesPerElement=\"1\">\n          "
            << xdmf::dataItem(ns + " 1", true, h5name, "/points/topology")
            << "\n        </Topology>\n"
            << "        <Geometry GeometryType=\"" << geomType << "\">\n          "
            << xdmf::dataItem(ns + " " + std::to_string(dim), false, h5name, "/points/geometry")
            << "\n        </Geometry>\n";
        }
        for (const Attribute &a : attributes(cells)) {
          const char *atype = a.components == 1   ? "Scalar"
                              : a.components == 3 ? "Vector"
                                                  : "Matrix";
          // Integers are [N, bs] even for bs = 1 (ISView).
          const std::string path = a.per_step ? a.path + "/" + std::to_string(s) : a.path;
          const std::string rows = a.node && cells ? std::to_string(num_nodes) : ns;
          const std::string dims =
              a.components == 1 && !a.integer ? rows : rows + " " + std::to_string(a.components);
          x << "        <Attribute Name=\"" << a.name << "\" AttributeType=\"" << atype
            << "\" Center=\"" << (cells && !a.node ? "Cell" : "Node") << "\">\n          "
            << xdmf::dataItem(dims, a.integer, h5name, path) << "\n        </Attribute>\n";
        }
        x << "      </Grid>\n";
      }
      x << "    </Grid>\n";
      x << "  </Domain>\n"
        << "</Xdmf>\n";
    }
    failed = true; // until the index is written: a close after this error writes nothing more
    PetscCall(xdmf::replaceFile(comm, xmfPath[grid], x.str(), kWho));
    failed = false;
  }
  PetscFunctionReturn(0);
}

} // namespace poroseam
