// XDMF 3 with its heavy data in HDF5: x.xdmf (XML) and its sibling x.h5, the layout dolfinx's
// XDMFFile writes (dolfinx 0.5, cpp/dolfinx/io/XDMFFile.cpp write_mesh and write_meshtags, and
// xdmf_mesh.cpp; checked against what python3-dolfinx 0.5.2 writes for a unit cube with its
// meshtags). The XDMF model: https://www.xdmf.org/index.php/XDMF_Model_and_Format.
//
// x.xdmf holds one Domain with three Uniform grids:
//   "mesh"        Topology "Tetrahedron" and Geometry "XYZ"
//                 -> x.h5:/Mesh/mesh/topology (T x 4 int64, 0-based point indices),
//                    x.h5:/Mesh/mesh/geometry (N x 3 float64)
//   "facet_tags"  the boundary faces as a "Triangle" topology, the mesh's geometry through
//                 XInclude (xpointer(/Xdmf/Domain/Grid/Geometry): the first grid's, dolfinx's own
//                 default), and the boundary tags as a scalar Attribute on cells
//                 -> x.h5:/MeshTags/facet_tags/topology (F x 3 int64), .../Values (F x 1 int32)
//   "cell_tags"   the tets again, with their regions -> x.h5:/MeshTags/cell_tags/Values, and
//                 .../topology, a hard link to /Mesh/mesh/topology (the same tets in the same
//                 order: 40 % of the .h5 for the femur's 204 k tets, not written twice)
// dolfinx's read_meshtags finds each tagged entity by its vertices, so any order of faces or cells
// works. A second-order mesh is written as dolfinx 0.5.2 writes a mesh of P2 geometry (checked:
// XDMFFile.write_mesh and write_meshtags on a 10-node box from Gmsh): "Tetrahedron_10" (T x 10)
// and "Triangle_6" (F x 6), the corners first, then the mid-edge nodes in VTK's order, kTetEdges'
// for tets and (0,1) (1,2) (2,0) for triangles. Node order: XDMF's Tetrahedron is VTK's, whose positive volume is TetMesh's
// ((p1-p0).((p2-p0)x(p3-p0)) > 0); triangles are outward, as in TetMesh. The DataItems also state
// NumberType and Precision, which dolfinx leaves to their defaults (Float, 4) although its data is
// 8 bytes wide; readers of HDF data take the type from the dataset.
//
// The names of the tags: one <Information Name="<name>" Value="<tag>"/> per tag in the grid of the
// tags ("facet_tags": boundary_names, "cell_tags": region_names), so that a dolfinx script finds a
// patch's tag by its name with an XML parser; each tag in use is named, by its default name
// (patch_names.h, tag_name: "boundary_<t>", "region_<r>") where the mesh has none. Names follow
// patch_names.h's rule (write_tet_mesh checks them), so they need no XML escaping.
//
// Both files are written as temporaries, the .h5 inside the .xdmf's write, then renamed .h5 first,
// as the TetGen writer does with its three files: a failure while writing leaves neither behind.
#include "exporters.h"
#include "hdf5_file.h"

#include "meshprep/core/atomic_file.h"
#include "meshprep/core/errors.h"
#include "meshprep/core/patch_names.h"
#include "meshprep/report/html_report.h"  // escape: for XML too

#include <array>
#include <cstdint>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace meshprep::detail {
namespace {

// Writes the heavy data into one HDF5 file; every failure is a WriteError naming the .xdmf
// (`shown`), the dataset and HDF5's reason.
class HeavyDataWriter {
 public:
  HeavyDataWriter(const std::string& file, const std::string& shown)
      : shown_(shown), file_(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose) {
    if (!file_.valid()) fail("the HDF5 file");
  }

  // A rows x columns dataset of `file_type` at `path` (its groups created on the way), filled from
  // `data` (rows * columns values of `memory_type`).
  void dataset(const std::string& path, hid_t file_type, hid_t memory_type, std::size_t rows, std::size_t columns,
               const void* data) {
    const hsize_t dims[2] = {rows, columns};
    const Hdf5Handle space(H5Screate_simple(2, dims, nullptr), H5Sclose);
    const Hdf5Handle links(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
    if (!space.valid() || !links.valid() || H5Pset_create_intermediate_group(links.get(), 1) < 0) fail(path);
    Hdf5Handle set(H5Dcreate2(file_.get(), path.c_str(), file_type, space.get(), links.get(), H5P_DEFAULT, H5P_DEFAULT),
                   H5Dclose);
    if (!set.valid()) fail(path);
    // An empty dataset has nothing to write (and HDF5 wants a buffer for H5Dwrite).
    if (rows > 0 && H5Dwrite(set.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0) fail(path);
    if (!set.close()) fail(path);
  }

  // A second name for the dataset at `path` (an HDF5 hard link, its groups created on the way).
  void link(const std::string& path, const std::string& second_path) {
    const Hdf5Handle links(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
    if (!links.valid() || H5Pset_create_intermediate_group(links.get(), 1) < 0 ||
        H5Lcreate_hard(file_.get(), path.c_str(), file_.get(), second_path.c_str(), links.get(), H5P_DEFAULT) < 0)
      fail(second_path);
  }

  // Closing the file flushes it: a full disk shows here.
  void close() {
    if (!file_.close()) fail("the HDF5 file");
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    const std::string reason = hdf5_reason();
    throw WriteError(shown_ + ": cannot write " + what + (reason.empty() ? "" : ": " + reason));
  }

  const std::string& shown_;
  Hdf5Handle file_;
};

template <std::size_t N>
std::vector<std::int64_t> flat_indices(const std::vector<std::array<std::uint32_t, N>>& elements) {
  std::vector<std::int64_t> flat;
  flat.reserve(elements.size() * N);
  for (const auto& element : elements) flat.insert(flat.end(), element.begin(), element.end());
  return flat;
}

void write_heavy_data(const TetMesh& mesh, const std::string& file, const std::string& shown) {
  const Hdf5Quiet quiet;
  HeavyDataWriter out(file, shown);
  std::vector<double> coordinates;
  coordinates.reserve(mesh.points.size() * 3);
  for (const Vec3& p : mesh.points) coordinates.insert(coordinates.end(), {p.x(), p.y(), p.z()});
  const bool p2 = mesh.quadratic();
  const std::vector<std::int64_t> tets = p2 ? flat_indices(with_nodes(mesh.tets, mesh.tet_edge_nodes)) : flat_indices(mesh.tets);
  const std::vector<std::int64_t> faces = p2 ? flat_indices(with_nodes(mesh.boundary_faces, boundary_face_edge_nodes(mesh)))
                                             : flat_indices(mesh.boundary_faces);
  out.dataset("/Mesh/mesh/geometry", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, mesh.points.size(), 3, coordinates.data());
  out.dataset("/Mesh/mesh/topology", H5T_STD_I64LE, H5T_NATIVE_INT64, mesh.tets.size(), p2 ? 10 : 4, tets.data());
  out.dataset("/MeshTags/facet_tags/topology", H5T_STD_I64LE, H5T_NATIVE_INT64, mesh.boundary_faces.size(), p2 ? 6 : 3,
              faces.data());
  out.dataset("/MeshTags/facet_tags/Values", H5T_STD_I32LE, H5T_NATIVE_INT, mesh.boundary_tags.size(), 1,
              mesh.boundary_tags.data());
  // The cell tags are on every tet in mesh order: their topology is the mesh's, stored once.
  out.link("/Mesh/mesh/topology", "/MeshTags/cell_tags/topology");
  out.dataset("/MeshTags/cell_tags/Values", H5T_STD_I32LE, H5T_NATIVE_INT, mesh.tet_regions.size(), 1,
              mesh.tet_regions.data());
  out.close();
}

// The name of each tag in use: the mesh's, else the default one (as the Gmsh writer names them).
TagNames names_to_write(const TagNames& names, const std::vector<int>& tags, const char* prefix) {
  TagNames used;
  for (const int tag : distinct_tags(tags)) used.emplace(tag, tag_name(names, tag, prefix));
  return used;
}

class LightDataWriter {
 public:
  // The .h5 file's name is escaped for the DataItems' text: a file name may hold '&' or '<'.
  LightDataWriter(std::ostream& out, const std::string& h5_name) : out_(out), h5_(html::escape(h5_name)) {}

  void data_item(const char* indent, std::size_t rows, std::size_t columns, const char* number_type, int precision,
                 const std::string& dataset) {
    out_ << indent << "<DataItem Dimensions=\"" << rows << ' ' << columns << "\" NumberType=\"" << number_type
         << "\" Precision=\"" << precision << "\" Format=\"HDF\">" << h5_ << ':' << dataset << "</DataItem>\n";
  }

  void topology(const char* type, std::size_t count, std::size_t nodes, const std::string& dataset) {
    out_ << "      <Topology TopologyType=\"" << type << "\" NumberOfElements=\"" << count << "\" NodesPerElement=\""
         << nodes << "\">\n";
    data_item("        ", count, nodes, "Int", 8, dataset);
    out_ << "      </Topology>\n";
  }

  void tag_grid(const char* name, const char* type, std::size_t count, std::size_t nodes, const TagNames& names) {
    const std::string prefix = std::string("/MeshTags/") + name;
    out_ << "    <Grid Name=\"" << name << "\" GridType=\"Uniform\">\n"
         << "      <xi:include xpointer=\"xpointer(/Xdmf/Domain/Grid/Geometry)\" />\n";
    topology(type, count, nodes, prefix + "/topology");
    out_ << "      <Attribute Name=\"" << name << "\" AttributeType=\"Scalar\" Center=\"Cell\">\n";
    data_item("        ", count, 1, "Int", 4, prefix + "/Values");
    out_ << "      </Attribute>\n";
    for (const auto& [tag, label] : names)
      out_ << "      <Information Name=\"" << label << "\" Value=\"" << tag << "\" />\n";
    out_ << "    </Grid>\n";
  }

  void write(const TetMesh& mesh) {
    out_ << "<?xml version=\"1.0\"?>\n"
         << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
         << "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
         << "  <Domain>\n"
         << "    <Grid Name=\"mesh\" GridType=\"Uniform\">\n";
    const bool p2 = mesh.quadratic();
    const char* tetrahedron = p2 ? "Tetrahedron_10" : "Tetrahedron";
    topology(tetrahedron, mesh.tets.size(), p2 ? 10 : 4, "/Mesh/mesh/topology");
    out_ << "      <Geometry GeometryType=\"XYZ\">\n";
    data_item("        ", mesh.points.size(), 3, "Float", 8, "/Mesh/mesh/geometry");
    out_ << "      </Geometry>\n"
         << "    </Grid>\n";
    tag_grid("facet_tags", p2 ? "Triangle_6" : "Triangle", mesh.boundary_faces.size(), p2 ? 6 : 3,
             names_to_write(mesh.boundary_names, mesh.boundary_tags, "boundary"));
    tag_grid("cell_tags", tetrahedron, mesh.tets.size(), p2 ? 10 : 4,
             names_to_write(mesh.region_names, mesh.tet_regions, "region"));
    out_ << "  </Domain>\n"
         << "</Xdmf>\n";
  }

 private:
  std::ostream& out_;
  std::string h5_;
};

}  // namespace

void write_xdmf(const TetMesh& mesh, const std::string& path) {
  const std::filesystem::path h5_path = std::filesystem::path(path).replace_extension(".h5");
  write_file_atomically(path, [&](std::ostream& out) {
    LightDataWriter(out, h5_path.filename().string()).write(mesh);
    out.flush();
    write_path_atomically(h5_path.string(), [&](const std::string& file) { write_heavy_data(mesh, file, path); });
  });
}

}  // namespace meshprep::detail
