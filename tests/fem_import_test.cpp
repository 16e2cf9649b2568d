// read_tet_mesh: round trips through every writer, files written by Gmsh and meshio, small
// hand-written files, malformed files, orientation and the boundary.
#include "hdf5_file.h"  // fem/src: the HDF5 handle that closes itself
#include "meshprep/core/errors.h"
#include "meshprep/fem/export.h"
#include "meshprep/fem/import.h"
#include "meshprep/fem/tet_quality.h"
#include "scratch_dir.h"
#include "third_party_tools.h"
#include "tet_test_meshes.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace meshprep {
namespace {

using test::has_gmsh;
using test::python_with_meshio;
using test::succeeds;

void write_text(const std::string& path, const std::string& content) {
  std::ofstream out(path, std::ios::binary);
  out << content;
}

// The cube of cube_tets(2) (two regions, six boundary tags) moved and scaled so that its
// coordinates need all 17 significant digits; one region and two sides are named.
TetMesh odd_cube() {
  TetMesh mesh = test::cube_tets(2, 1.0 / 3.0);
  for (Vec3& p : mesh.points) p = p * 1.1 + Vec3(0.1, -2.5e-7, 1e5 / 7.0);
  mesh.region_names = {{1, "core"}};
  mesh.boundary_names = {{1, "fixed_end"}, {4, "Load"}};
  return mesh;
}

double tets_volume(const TetMesh& mesh) {
  double volume = 0;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) volume += tet_volume(mesh, t);
  return volume;
}

using Face = std::array<std::uint32_t, 3>;

Face sorted(Face f) {
  std::sort(f.begin(), f.end());
  return f;
}

// The same oriented triangle whatever corner it starts with.
Face rotated_to_smallest(const Face& f) {
  const auto k = static_cast<std::size_t>(std::min_element(f.begin(), f.end()) - f.begin());
  return {f[k], f[(k + 1) % 3], f[(k + 2) % 3]};
}

// The faces with exactly one tet (sorted corners -> the tet's fourth corner), counted by brute force.
std::map<Face, std::uint32_t> faces_with_one_tet(const TetMesh& mesh) {
  std::map<Face, std::pair<int, std::uint32_t>> faces;
  for (const Tetrahedron& t : mesh.tets)
    for (int k = 0; k < 4; ++k) {
      Face f{t[(k + 1) % 4], t[(k + 2) % 4], t[(k + 3) % 4]};
      auto& entry = faces[sorted(f)];
      ++entry.first;
      entry.second = t[k];
    }
  std::map<Face, std::uint32_t> once;
  for (const auto& [face, entry] : faces)
    if (entry.first == 1) once[face] = entry.second;
  return once;
}

// Checks the boundary promises of import.h: every face of one tet is in boundary_faces, oriented
// away from its tet, and the flux of x / 3 through the boundary is the tets' volume (divergence
// theorem; the points are moved to the first one's frame so that a far origin costs no digits).
void expect_outward_boundary(const TetMesh& mesh) {
  const std::map<Face, std::uint32_t> once = faces_with_one_tet(mesh);
  std::size_t found = 0;
  double flux = 0;
  const Vec3 origin = mesh.points.front();
  for (const Face& f : mesh.boundary_faces) {
    const auto it = once.find(sorted(f));
    if (it == once.end()) continue;  // an interface face
    ++found;
    const Vec3 a = mesh.points[f[0]] - origin, b = mesh.points[f[1]] - origin, c = mesh.points[f[2]] - origin;
    const Vec3 area = (b - a).cross(c - a) / 2.0;
    EXPECT_LT(area.dot(mesh.points[it->second] - origin - a), 0) << "face " << f[0] << " " << f[1] << " " << f[2];
    flux += ((a + b + c) / 3.0).dot(area) / 3.0;
  }
  EXPECT_EQ(found, once.size());
  const double volume = tets_volume(mesh);
  EXPECT_NEAR(flux, volume, 1e-12 * std::abs(volume));
}

bool same_point(const Vec3& a, const Vec3& b) { return a.x() == b.x() && a.y() == b.y() && a.z() == b.z(); }

void expect_same_points(const TetMesh& expected, const TetMesh& read) {
  ASSERT_EQ(read.points.size(), expected.points.size());
  for (std::size_t p = 0; p < expected.points.size(); ++p)
    EXPECT_TRUE(same_point(read.points[p], expected.points[p])) << "point " << p;
}

void expect_identical(const TetMesh& expected, const TetMesh& read) {
  expect_same_points(expected, read);
  EXPECT_EQ(read.tets, expected.tets);
  EXPECT_EQ(read.tet_regions, expected.tet_regions);
  EXPECT_EQ(read.boundary_faces, expected.boundary_faces);
  EXPECT_EQ(read.boundary_tags, expected.boundary_tags);
}

// Oriented boundary faces (rotated to their smallest corner) -> tag.
std::map<Face, int> tagged_faces(const TetMesh& mesh) {
  std::map<Face, int> faces;
  for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f)
    faces[rotated_to_smallest(mesh.boundary_faces[f])] = mesh.boundary_tags[f];
  return faces;
}

// Sorted tet corners -> region.
std::map<Tetrahedron, int> tets_by_corners(const TetMesh& mesh) {
  std::map<Tetrahedron, int> tets;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    Tetrahedron c = mesh.tets[t];
    std::sort(c.begin(), c.end());
    tets[c] = mesh.tet_regions[t];
  }
  return tets;
}

// The keys of a map, without the tags.
template <class Key>
std::set<Key> untagged(const std::map<Key, int>& tagged) {
  std::set<Key> keys;
  for (const auto& entry : tagged) keys.insert(entry.first);
  return keys;
}

class FemImportTest : public test::ScratchDirTest {
 protected:
  // Reads `read_as` (default: `name`), expecting an InvalidInput whose one-line message names the
  // file `name` and holds `fragment`.
  void expect_refused(const std::string& name, const std::string& fragment, std::string read_as = "") const {
    try {
      read_tet_mesh(path(read_as.empty() ? name : read_as));
      ADD_FAILURE() << name << ": read without error";
    } catch (const InvalidInput& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(path(name)), std::string::npos) << message;
      EXPECT_NE(message.find(fragment), std::string::npos) << "expected '" << fragment << "' in: " << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
  void expect_refused_text(const std::string& name, const std::string& content, const std::string& fragment,
                           const std::string& read_as = "") const {
    write_text(path(name), content);
    expect_refused(name, fragment, read_as);
  }
};

// ---- round trips through write_tet_mesh ----

struct Variant {
  const char* file;
  TetExportOptions options;
  bool stores_boundary;  // legacy VTK stores the tets only
  bool stores_names = false;
};

class RoundTrip : public FemImportTest, public ::testing::WithParamInterface<Variant> {};

TEST_P(RoundTrip, ReadsBackWhatWasWritten) {
  const TetMesh mesh = odd_cube();
  write_tet_mesh(mesh, path(GetParam().file), GetParam().options);
  TetReadReport report;
  const TetMesh read = read_tet_mesh(path(GetParam().file), &report);
  EXPECT_EQ(report.path, path(GetParam().file));
  EXPECT_EQ(report.tets_reoriented, 0u);
  EXPECT_EQ(report.interface_faces, 0u);
  if (GetParam().stores_boundary) {
    expect_identical(mesh, read);
    EXPECT_EQ(report.triangles_in_file, mesh.boundary_faces.size());
    EXPECT_EQ(report.untagged_boundary_faces, 0u);
  } else {
    expect_same_points(mesh, read);
    EXPECT_EQ(read.tets, mesh.tets);
    EXPECT_EQ(read.tet_regions, mesh.tet_regions);
    std::map<Face, int> expected = tagged_faces(mesh);
    for (auto& [face, tag] : expected) tag = 1;
    EXPECT_EQ(tagged_faces(read), expected);
    EXPECT_EQ(report.untagged_boundary_faces, mesh.boundary_faces.size());
  }
  expect_outward_boundary(read);
  if (GetParam().stores_names) {
    // The names the mesh has, and the writer's defaults for the other tags.
    EXPECT_EQ(read.region_names, (TagNames{{1, "core"}, {2, "region_2"}}));
    TagNames boundary{{1, "fixed_end"}, {4, "Load"}};
    for (const int tag : {2, 3, 5, 6}) boundary[tag] = "boundary_" + std::to_string(tag);
    EXPECT_EQ(read.boundary_names, boundary);
  }
}

INSTANTIATE_TEST_SUITE_P(EveryWriter, RoundTrip,
                         ::testing::Values(Variant{"v41_ascii.msh", {MshVersion::V41, false}, true, true},
                                           Variant{"v41_binary.msh", {MshVersion::V41, true}, true, true},
                                           Variant{"v22_ascii.msh", {MshVersion::V22, false}, true, true},
                                           Variant{"v22_binary.msh", {MshVersion::V22, true}, true, true},
                                           Variant{"cube.mesh", {}, true}, Variant{"cube.node", {}, true},
                                           Variant{"cube.vtu", {}, true},
                                           Variant{"ascii.vtu", {MshVersion::V41, false, true}, true},
                                           Variant{"cube.vtk", {}, false},
                                           Variant{"cube.xdmf", {}, true}),
                         [](const auto& test_info) {
                           std::string name = test_info.param.file;
                           std::replace(name.begin(), name.end(), '.', '_');
                           return name;
                         });

TEST_F(FemImportTest, TetgenReadsFromTheEleAndWithoutFace) {
  const TetMesh mesh = odd_cube();
  write_tet_mesh(mesh, path("cube.node"));
  expect_identical(mesh, read_tet_mesh(path("cube.ele")));
  std::filesystem::remove(path("cube.face"));
  const TetMesh read = read_tet_mesh(path("cube.node"));
  EXPECT_EQ(read.tets, mesh.tets);
  EXPECT_EQ(read.boundary_faces.size(), mesh.boundary_faces.size());
  EXPECT_TRUE(std::all_of(read.boundary_tags.begin(), read.boundary_tags.end(), [](int tag) { return tag == 1; }));
}

TEST_F(FemImportTest, ExtensionIsCaseInsensitive) {
  const TetMesh mesh = test::cube_tets(1);
  write_tet_mesh(mesh, path("A.MSH"));
  expect_identical(mesh, read_tet_mesh(path("A.MSH")));
  write_tet_mesh(mesh, path("B.NODE"));  // the writer names the siblings .ele and .face
  std::filesystem::rename(path("B.ele"), path("B.ELE"));
  std::filesystem::rename(path("B.face"), path("B.FACE"));
  expect_identical(mesh, read_tet_mesh(path("B.NODE")));
}

// Triangles between two regions are kept with their tags, after being checked to be tet faces.
TEST_F(FemImportTest, InterfaceTrianglesAreKept) {
  TetMesh mesh = test::cube_tets(2);
  const std::size_t outer = mesh.boundary_faces.size();
  // The faces in the plane x = 0.5, between region 1 and region 2.
  std::set<Face> interface;
  for (const Tetrahedron& t : mesh.tets)
    for (int k = 0; k < 4; ++k) {
      const Face f{t[(k + 1) % 4], t[(k + 2) % 4], t[(k + 3) % 4]};
      if (std::all_of(f.begin(), f.end(), [&](std::uint32_t v) { return mesh.points[v].x() == 0.5; }))
        interface.insert(sorted(f));
    }
  ASSERT_EQ(interface.size(), 8u);
  for (const Face& f : interface) {
    mesh.boundary_faces.push_back(f);
    mesh.boundary_tags.push_back(7);
  }
  for (const char* name : {"i.msh", "i.mesh", "i.node", "i.xdmf", "i.vtu"}) {
    write_tet_mesh(mesh, path(name));
    TetReadReport report;
    const TetMesh read = read_tet_mesh(path(name), &report);
    expect_identical(mesh, read);
    EXPECT_EQ(report.interface_faces, 8u) << name;
    EXPECT_EQ(report.internal_faces, 0u) << name;  // between the two regions
    EXPECT_EQ(std::count(read.boundary_tags.begin() + static_cast<std::ptrdiff_t>(outer), read.boundary_tags.end(), 7), 8)
        << name;
    expect_outward_boundary(read);
  }
}

// ---- files written by other programs ----

const char* const box_geo =
    "SetFactory(\"OpenCASCADE\");\n"
    "Box(1) = {0, 0, 0, 1, 1, 1};\n"
    "Mesh.MeshSizeMax = 0.4;\n";

// Every boundary face of the unit box lies in one of its six sides.
bool on_a_side(const TetMesh& mesh, const Face& f) {
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {0.0, 1.0})
      if (std::all_of(f.begin(), f.end(), [&](std::uint32_t v) { return std::abs(mesh.points[v][axis] - side) < 1e-12; }))
        return true;
  return false;
}

void expect_unit_box(const TetMesh& mesh, const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_NEAR(tets_volume(mesh), 1.0, 1e-12);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) ASSERT_GT(tet_volume(mesh, t), 0) << "tet " << t;
  for (const Face& f : mesh.boundary_faces) EXPECT_TRUE(on_a_side(mesh, f));
  expect_outward_boundary(mesh);
}

TEST_F(FemImportTest, ReadsWhatGmshWrites) {
  if (!has_gmsh()) GTEST_SKIP() << "gmsh is not on PATH (apt-get install gmsh)";
  write_text(path("box.geo"), box_geo);
  // With physical groups Gmsh saves only their elements: the volume as region 5, the side x = 0
  // (surface 1 of the OpenCASCADE box) as tag 3; without, it saves every element with tag 0.
  write_text(path("tagged.geo"),
             std::string(box_geo) + "Physical Volume(5) = {1};\nPhysical Surface(\"fixed end\", 3) = {1};\n");
  struct Output {
    const char* file;
    const char* format;
    bool binary;
  };
  const Output outputs[] = {{"a22.msh", "msh22", false},
                            {"b22.msh", "msh22", true},
                            {"a41.msh", "msh41", false},
                            {"b41.msh", "msh41", true},
                            {"p41.msh", "msh41 -setnumber Mesh.SaveParametric 1", true},  // u, v after x y z
                            {"a.vtk", "vtk", false},
                            {"b.vtk", "vtk", true},
                            {"a.mesh", "mesh", false}};
  std::size_t num_tets = 0;
  for (const char* geo : {"box", "tagged"}) {
    for (const Output& o : outputs) {
      const std::string file = path(std::string(geo) + "_" + o.file);
      ASSERT_TRUE(succeeds("gmsh " + path(std::string(geo) + ".geo") + " -3 -v 0 -format " + o.format +
                           (o.binary ? " -bin" : "") + " -o " + file + " >/dev/null 2>&1"))
          << file;
      TetReadReport report;
      const TetMesh mesh = read_tet_mesh(file, &report);
      expect_unit_box(mesh, file);
      if (num_tets == 0) num_tets = mesh.tets.size();
      EXPECT_EQ(mesh.tets.size(), num_tets) << file << ": the same mesh in every format";
      const bool physical = std::string(geo) == "tagged" && std::string(o.format).rfind("msh", 0) == 0;
      if (!physical) continue;
      EXPECT_TRUE(std::all_of(mesh.tet_regions.begin(), mesh.tet_regions.end(), [](int r) { return r == 5; })) << file;
      EXPECT_EQ(mesh.boundary_names, (TagNames{{3, "fixed_end"}})) << file;  // the name made to follow the rule
      ASSERT_EQ(report.renamed_names.size(), 1u) << file;
      EXPECT_EQ(report.renamed_names[0].from, "fixed end") << file;
      for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f) {
        const Face& face = mesh.boundary_faces[f];
        const bool x0 = std::all_of(face.begin(), face.end(), [&](std::uint32_t v) { return mesh.points[v].x() == 0; });
        EXPECT_EQ(mesh.boundary_tags[f], x0 ? 3 : 1) << file << " face " << f;
      }
    }
  }
  // Without physical groups Gmsh also saves points and lines, which are skipped.
  TetReadReport report;
  read_tet_mesh(path("box_a41.msh"), &report);
  EXPECT_GT(report.elements_ignored, 0u);
  EXPECT_EQ(report.format, "msh 4.1 ascii");
}

// meshio rewrites our .mesh (boundary triangles with tags, tets with regions) in its formats.
const char* const meshio_script = R"(
import sys
import meshio
import numpy
source, out = sys.argv[1], sys.argv[2]
m = meshio.read(source, file_format="medit")
ref = m.cell_data["medit:ref"]
# meshio's MSH 4.1 writer needs an entity per node when there are several cell types.
dim_tags = numpy.tile([3, 1], (len(m.points), 1))
mio = meshio.Mesh(m.points, m.cells, point_data={"gmsh:dim_tags": dim_tags},
                  cell_data={"gmsh:physical": ref, "gmsh:geometrical": ref})
meshio.write(out + "/zlib.vtu", m, binary=True, compression="zlib")
meshio.write(out + "/zlib64.vtu", m, binary=True, compression="zlib", header_type="UInt64")
meshio.write(out + "/base64.vtu", m, binary=True, compression=None)
meshio.write(out + "/ascii.vtu", m, binary=False)
meshio.write(out + "/v51_binary.vtk", m, binary=True)
meshio.write(out + "/v51_ascii.vtk", m, binary=False)
meshio.write(out + "/v42_binary.vtk", m, file_format="vtk42", binary=True)
meshio.write(out + "/medit.mesh", m)
meshio.write(out + "/v22_binary.msh", mio, file_format="gmsh22", binary=True)
meshio.write(out + "/v41_binary.msh", mio, file_format="gmsh", binary=True)
tets = [c for c in m.cells if c.type == "tetra"]
tet_ref = [r for c, r in zip(m.cells, ref) if c.type == "tetra"]
meshio.write(out + "/tetgen.node", meshio.Mesh(m.points, tets, cell_data={"tetgen:ref": tet_ref}))
# One cell type: with several, meshio writes a Mixed topology, which meshprep does not read.
meshio.write(out + "/meshio.xdmf", meshio.Mesh(m.points, tets, cell_data={"gmsh:physical": tet_ref}))
)";

TEST_F(FemImportTest, ReadsWhatMeshioWrites) {
  const std::string python = python_with_meshio();
  if (python.empty()) GTEST_SKIP() << "no python3 with meshio and numpy (apt-get install python3-meshio)";
  const TetMesh mesh = odd_cube();
  write_tet_mesh(mesh, path("cube.mesh"));
  write_text(path("rewrite.py"), meshio_script);
  ASSERT_TRUE(succeeds(python + " " + path("rewrite.py") + " " + path("cube.mesh") + " " + dir_.string() +
                       " >/dev/null 2>&1"));
  const std::map<Tetrahedron, int> tets = tets_by_corners(mesh);
  const std::map<Face, int> faces = tagged_faces(mesh);
  for (const char* file : {"zlib.vtu", "zlib64.vtu", "base64.vtu", "ascii.vtu", "v51_binary.vtk", "v51_ascii.vtk",
                           "v42_binary.vtk", "medit.mesh", "v22_binary.msh", "v41_binary.msh", "tetgen.node",
                           "meshio.xdmf"}) {
    SCOPED_TRACE(file);
    TetReadReport report;
    const TetMesh read = read_tet_mesh(path(file), &report);
    // meshio writes text coordinates with 11 or 16 digits after the point, binary ones exactly.
    const bool text = std::string(file).find("ascii") != std::string::npos || std::string(file) == "medit.mesh" ||
                      std::string(file) == "tetgen.node";
    ASSERT_EQ(read.points.size(), mesh.points.size());
    for (std::size_t p = 0; p < mesh.points.size(); ++p) {
      if (text)
        EXPECT_LT((read.points[p] - mesh.points[p]).norm(), 1e-10 * mesh.points[p].norm()) << "point " << p;
      else
        EXPECT_TRUE(same_point(read.points[p], mesh.points[p])) << "point " << p;
    }
    // meshio's MSH 4.1 writer puts each element block in the entity its gmsh:geometrical names but
    // declares only volume 1 in $Entities, with physical tag 1: the other tags are lost.
    const bool tags_kept = std::string(file) != "v41_binary.msh";
    EXPECT_EQ(untagged(tets_by_corners(read)), untagged(tets));
    EXPECT_EQ(untagged(tagged_faces(read)), untagged(faces));
    if (tags_kept) {
      EXPECT_EQ(tets_by_corners(read), tets);
    }
    if (std::string(file) == "tetgen.node" || std::string(file) == "meshio.xdmf") {  // tets only
      EXPECT_EQ(report.untagged_boundary_faces, faces.size());
    } else {
      if (tags_kept) {
        EXPECT_EQ(tagged_faces(read), faces);
      }
      EXPECT_EQ(report.untagged_boundary_faces, 0u);
    }
    expect_outward_boundary(read);
  }
}

// dolfinx 0.5's XDMFFile: a unit cube (2 x 2 x 2 cells of 6 tets), the facets on x = 0 tagged 7,
// the cells with every vertex at x <= 0.5 tagged 3, written in HDF5 and in ASCII (inline XML).
const char* const dolfinx_script = R"(
import sys
import numpy as np
from mpi4py import MPI
from dolfinx import io, mesh as dmesh
out = sys.argv[1]
m = dmesh.create_unit_cube(MPI.COMM_WORLD, 2, 2, 2, dmesh.CellType.tetrahedron)
tdim = m.topology.dim
m.topology.create_connectivity(tdim - 1, tdim)
facets = dmesh.locate_entities_boundary(m, tdim - 1, lambda x: np.isclose(x[0], 0.0))
facet_tags = dmesh.meshtags(m, tdim - 1, facets, np.full(len(facets), 7, dtype=np.int32))
facet_tags.name = "facet_tags"
cells = dmesh.locate_entities(m, tdim, lambda x: x[0] <= 0.5 + 1e-12)
cell_tags = dmesh.meshtags(m, tdim, cells, np.full(len(cells), 3, dtype=np.int32))
cell_tags.name = "cell_tags"
for name, encoding in (("hdf", io.XDMFFile.Encoding.HDF5), ("ascii", io.XDMFFile.Encoding.ASCII)):
    with io.XDMFFile(MPI.COMM_WORLD, out + "/" + name + ".xdmf", "w", encoding=encoding) as f:
        f.write_mesh(m)
        f.write_meshtags(facet_tags)
        f.write_meshtags(cell_tags)
)";

TEST_F(FemImportTest, ReadsWhatDolfinxWrites) {
  const std::string python = test::python_with("dolfinx");
  if (python.empty()) GTEST_SKIP() << "no python3 with dolfinx (apt-get install python3-dolfinx)";
  write_text(path("write.py"), dolfinx_script);
  ASSERT_TRUE(succeeds(python + " " + path("write.py") + " " + dir_.string() + " >/dev/null 2>&1"));
  for (const char* file : {"hdf.xdmf", "ascii.xdmf"}) {
    SCOPED_TRACE(file);
    TetReadReport report;
    const TetMesh mesh = read_tet_mesh(path(file), &report);
    EXPECT_EQ(report.format, std::string(file) == "hdf.xdmf" ? "xdmf 3.0 hdf5" : "xdmf 3.0 xml");
    EXPECT_EQ(mesh.points.size(), 27u);
    EXPECT_EQ(mesh.tets.size(), 48u);
    expect_unit_box(mesh, file);
    EXPECT_EQ(report.triangles_in_file, 8u);
    EXPECT_EQ(report.untagged_boundary_faces, 40u);
    for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f) {
      const Face& face = mesh.boundary_faces[f];
      const bool x0 = std::all_of(face.begin(), face.end(), [&](std::uint32_t v) { return mesh.points[v].x() == 0; });
      EXPECT_EQ(mesh.boundary_tags[f], x0 ? 7 : 1) << "face " << f;
    }
    std::size_t tagged = 0;
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
      const bool left = std::all_of(mesh.tets[t].begin(), mesh.tets[t].end(),
                                    [&](std::uint32_t v) { return mesh.points[v].x() <= 0.5; });
      EXPECT_EQ(mesh.tet_regions[t], left ? 3 : 1) << "tet " << t;
      tagged += left;
    }
    EXPECT_EQ(tagged, 24u);
    EXPECT_TRUE(mesh.boundary_names.empty());
  }
}

TEST_F(FemImportTest, XdmfReadsBackTheNames) {
  TetMesh mesh = odd_cube();
  mesh.boundary_names = {{1, "inlet"}, {6, "Top_Wall"}};
  mesh.region_names = {{2, "steel"}};
  write_tet_mesh(mesh, path("named.xdmf"));
  const TetMesh read = read_tet_mesh(path("named.xdmf"));
  expect_identical(mesh, read);
  EXPECT_EQ(read.boundary_names, mesh.boundary_names);  // the default names of tags 2 to 5 left out
  EXPECT_EQ(read.region_names, mesh.region_names);
}

// ---- VTU and its boundary-faces file ----

TEST_F(FemImportTest, VtuReadsBackTheNamesAndSaysWhatItRead) {
  TetMesh mesh = odd_cube();
  mesh.boundary_names = {{1, "inlet"}, {6, "Top_Wall"}};
  mesh.region_names = {{2, "steel"}};
  for (const auto& [name, ascii, format] : {std::tuple{"binary.vtu", false, "vtu appended raw zlib + binary_boundary.vtu"},
                                            std::tuple{"ascii.vtu", true, "vtu ascii + ascii_boundary.vtu"}}) {
    SCOPED_TRACE(name);
    write_tet_mesh(mesh, path(name), {MshVersion::V41, false, ascii});
    TetReadReport report;
    const TetMesh read = read_tet_mesh(path(name), &report);
    expect_identical(mesh, read);
    EXPECT_EQ(read.boundary_names, mesh.boundary_names);  // the default names of tags 2 to 5 left out
    EXPECT_EQ(read.region_names, mesh.region_names);
    EXPECT_EQ(report.format, format);
  }
}

// Coordinates and ids spanning many of zlib's 32 KiB blocks come back bit for bit.
TEST_F(FemImportTest, VtuOfManyCompressedBlocksRoundTripsExactly) {
  TetMesh mesh = test::cube_tets(12, 1.0 / 3.0);  // 2197 points: 52 KiB of coordinates
  for (Vec3& p : mesh.points) p = p * 1.1 + Vec3(0.1, -2.5e-7, 1e5 / 7.0);
  write_tet_mesh(mesh, path("big.vtu"));
  expect_identical(mesh, read_tet_mesh(path("big.vtu")));
}

// Without its boundary file a .vtu is the tets alone: their boundary, untagged; a file of that
// name that is not meshprep's (no mesh_point_id) is not read.
TEST_F(FemImportTest, VtuWithoutItsBoundaryFileHasAnUntaggedBoundary) {
  const TetMesh mesh = odd_cube();
  write_tet_mesh(mesh, path("cube.vtu"));
  write_tet_mesh(mesh, path("other.vtu"));
  std::filesystem::rename(path("other.vtu"), path("cube_boundary.vtu"));  // tets, no mesh_point_id
  for (int pass = 0; pass < 2; ++pass) {
    TetReadReport report;
    const TetMesh read = read_tet_mesh(path("cube.vtu"), &report);
    EXPECT_EQ(report.format, "vtu appended raw zlib");
    EXPECT_EQ(read.tets, mesh.tets);
    EXPECT_EQ(untagged(tagged_faces(read)), untagged(tagged_faces(mesh)));
    EXPECT_EQ(report.untagged_boundary_faces, mesh.boundary_faces.size());
    std::filesystem::remove(path("cube_boundary.vtu"));
  }
}

// The boundary faces of another mesh are refused, not mixed in.
TEST_F(FemImportTest, VtuBoundaryFileOfAnotherMeshIsRefused) {
  TetMesh other = odd_cube();
  other.points[0].x() += 1e-9;
  write_tet_mesh(other, path("other.vtu"));
  write_tet_mesh(odd_cube(), path("cube.vtu"));
  std::filesystem::rename(path("other_boundary.vtu"), path("cube_boundary.vtu"));
  expect_refused("cube_boundary.vtu", "is not where point 0 of " + path("cube.vtu") + " is", "cube.vtu");
  // The same cube after 27 unused points: its boundary file names points 27 and up.
  const TetMesh cube = odd_cube();
  TetMesh shifted = cube;
  shifted.points.insert(shifted.points.begin(), cube.points.begin(), cube.points.end());
  for (Tetrahedron& t : shifted.tets)
    for (std::uint32_t& v : t) v += 27;
  for (Face& f : shifted.boundary_faces)
    for (std::uint32_t& v : f) v += 27;
  write_tet_mesh(shifted, path("shifted.vtu"));
  std::filesystem::rename(path("shifted_boundary.vtu"), path("cube_boundary.vtu"));
  expect_refused("cube_boundary.vtu",
                 "point #1 has mesh_point_id " + std::to_string(27 + cube.boundary_faces[0][0]) + ", but " +
                     path("cube.vtu") + " has 27 points (numbered from 0)",
                 "cube.vtu");
}

// The .h5's name is XML text in the .xdmf: written escaped, read unescaped.
TEST_F(FemImportTest, XdmfFileNameWithXmlCharacters) {
  const TetMesh mesh = test::cube_tets(1);
  const std::string name = "a&b's <1>";
  write_tet_mesh(mesh, path(name + ".xdmf"));
  EXPECT_TRUE(std::filesystem::exists(path(name + ".h5")));
  expect_identical(mesh, read_tet_mesh(path(name + ".xdmf")));
}

// ---- malformed XDMF ----

// One tet and one tagged face, every value inline (Format="XML").
const std::string inline_xdmf = R"xdmf(<?xml version="1.0"?>
<Xdmf Version="3.0" xmlns:xi="http://www.w3.org/2001/XInclude">
  <Domain>
    <Grid Name="mesh" GridType="Uniform">
      <Topology TopologyType="Tetrahedron" NumberOfElements="1" NodesPerElement="4">
        <DataItem Dimensions="1 4" NumberType="Int" Format="XML">0 1 2 3</DataItem>
      </Topology>
      <Geometry GeometryType="XYZ">
        <DataItem Dimensions="4 3" Format="XML">0 0 0 1 0 0 0 1 0 0 0 1</DataItem>
      </Geometry>
    </Grid>
    <Grid Name="facet_tags" GridType="Uniform">
      <xi:include xpointer="xpointer(/Xdmf/Domain/Grid/Geometry)" />
      <Topology TopologyType="Triangle" NumberOfElements="1" NodesPerElement="3">
        <DataItem Dimensions="1 3" NumberType="Int" Format="XML">0 2 1</DataItem>
      </Topology>
      <Attribute Name="facet_tags" AttributeType="Scalar" Center="Cell">
        <DataItem Dimensions="1" Format="XML">4</DataItem>
      </Attribute>
      <Information Name="bottom" Value="4" />
    </Grid>
  </Domain>
</Xdmf>
)xdmf";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST_F(FemImportTest, HandWrittenXdmfWithInlineData) {
  write_text(path("one.xdmf"), inline_xdmf);
  TetReadReport report;
  const TetMesh mesh = read_tet_mesh(path("one.xdmf"), &report);
  EXPECT_EQ(report.format, "xdmf 3.0 xml");
  EXPECT_EQ(mesh.tets, (std::vector<Tetrahedron>{{0, 1, 2, 3}}));
  EXPECT_EQ(mesh.boundary_faces.front(), (Face{0, 2, 1}));
  EXPECT_EQ(mesh.boundary_tags, (std::vector<int>{4, 1, 1, 1}));
  EXPECT_EQ(mesh.boundary_names, (TagNames{{4, "bottom"}}));
  EXPECT_EQ(mesh.tet_regions, (std::vector<int>{1}));
  // A name against the rule is made to follow it, and reported.
  write_text(path("renamed.xdmf"), replaced(inline_xdmf, "Name=\"bottom\"", "Name=\"the &amp; bottom\""));
  const TetMesh renamed = read_tet_mesh(path("renamed.xdmf"), &report);
  EXPECT_EQ(renamed.boundary_names, (TagNames{{4, "the_bottom"}}));
  ASSERT_EQ(report.renamed_names.size(), 1u);
  EXPECT_EQ(report.renamed_names[0].from, "the & bottom");
}

TEST_F(FemImportTest, MalformedInlineXdmfIsRefused) {
  const auto refused = [&](const std::string& from, const std::string& to, const std::string& fragment) {
    SCOPED_TRACE(from + " -> " + to);
    expect_refused_text("bad.xdmf", replaced(inline_xdmf, from, to), fragment);
  };
  refused("0 1 2 3", "0 1 2 9", "line 5: tetrahedron 1 references node 9, but the nodes are numbered 0 to 3");
  refused("0 2 1", "0 2 -1", "triangle 1 references node -1");
  expect_refused_text("bad.xdmf", replaced(replaced(inline_xdmf, "<Xdmf Version", "<Root Version"), "</Xdmf>", "</Root>"),
                      "not an XDMF file (no <Xdmf> element)");
  refused("  </Domain>\n", "", "line 22: </Xdmf> found where <Domain> (line 3) is open");
  refused("</Xdmf>", "", "<Xdmf> is not closed");
  refused("<Domain>", "<Domain", "malformed XML tag");
  refused("TopologyType=\"Tetrahedron\"", "TopologyType=\"Hexahedron\"", "TopologyType 'Hexahedron': meshprep reads Tetrahedron and Tetrahedron_10 only");
  refused("TopologyType=\"Tetrahedron\"", "TopologyType=\"Mixed\"", "TopologyType 'Mixed'");
  refused("NodesPerElement=\"4\"", "NodesPerElement=\"10\"", "not NodesPerElement='10'");
  refused("Format=\"XML\">0 1 2 3", "Format=\"Binary\">0 1 2 3", "DataItem Format 'Binary' is not read");
  refused("Dimensions=\"1 4\"", "Dimensions=\"1 3\"", "expected N 4 values");
  refused("Dimensions=\"1 4\"", "Dimensions=\"1 4 1\"", "is not one or two sizes");
  refused("<DataItem Dimensions=\"1 4\"", "<DataItem", "the DataItem has no Dimensions");
  refused("NumberOfElements=\"1\"", "NumberOfElements=\"2\"", "NumberOfElements='2', but the DataItem holds 1 cells");
  refused("0 0 0 1 0 0 0 1 0 0 0 1", "0 0 0 1 0 0 0 1 0 0 0", "holds 11 values, its Dimensions 12");
  refused("0 0 0 1 0 0 0 1 0 0 0 1", "0 0 0 1 0 0 0 1 0 0 0 1 5", "holds more than its 12 values");
  refused("0 0 0 1 0 0 0 1 0 0 0 1", "0 0 0 1 0 0 0 1 0 0 0 nan", "point #4 has a non-finite coordinate (nan)");
  refused("0 1 2 3</DataItem>", "0 1 2 x</DataItem>", "the DataItem's value 'x' is not an integer");
  refused("GeometryType=\"XYZ\"", "GeometryType=\"XY\"", "GeometryType XY: a tetrahedral mesh is 3D");
  refused("GeometryType=\"XYZ\"", "GeometryType=\"X_Y_Z\"", "GeometryType 'X_Y_Z' is not read");
  refused("<Grid Name=\"mesh\" GridType=\"Uniform\">", "<Grid Name=\"mesh\" GridType=\"Collection\">",
          "only Uniform grids are read");
  refused("Format=\"XML\">4<", "Format=\"XML\">4.5<", "the Attribute's value 4.5 is not an integer tag");
  refused("Format=\"XML\">4<", "Format=\"XML\">-4<", "triangle #1 has tag -4");
  refused("Dimensions=\"1\" Format=\"XML\">4<", "Dimensions=\"2\" Format=\"XML\">4 4<", "2 values for 1 cells");
  refused("<Information Name=\"bottom\" Value=\"4\" />", "<Information Name=\"a\" Value=\"4\" /><Information Name=\"b\" Value=\"4\" />",
          "tag 4 is named twice (a, b)");
  refused("Center=\"Cell\"", "Center=\"Node\"", "has no <Attribute> with Center=\"Cell\"");
  refused("0 2 1", "0 1 1", "triangle #1 repeats point #2");
  expect_refused_text("bad.xdmf", replaced(replaced(inline_xdmf, "<Geometry G", "<Geometr G"), "</Geometry>", "</Geometr>"),
                      "line 3: no <Grid> with a <Geometry> of its own");
  refused("Format=\"XML\">0 1 2 3", "Format=\"HDF\">0 1 2 3", "the HDF DataItem '0 1 2 3' is not FILE:/DATASET");
  refused("Format=\"XML\">0 1 2 3", "ItemType=\"HyperSlab\" Format=\"XML\">0 1 2 3", "ItemType 'HyperSlab' is not read");
  expect_refused_text("empty.xdmf", "", "empty file");
}

// A dataset of `type` (H5T_NATIVE_DOUBLE or H5T_NATIVE_INT64) added to an HDF5 file, `dims` of it,
// filled from `data`; chunked and unwritten when `data` is empty (it then stores no byte).
void add_dataset(const std::string& file, const char* name, hid_t type, std::vector<hsize_t> dims,
                 const std::vector<double>& data) {
  const detail::Hdf5Handle h5(H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose);
  const detail::Hdf5Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
  const detail::Hdf5Handle properties(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  const hsize_t chunk[2] = {1024, dims.size() > 1 ? dims[1] : 1};
  if (data.empty()) H5Pset_chunk(properties.get(), static_cast<int>(dims.size()), chunk);
  const detail::Hdf5Handle set(
      H5Dcreate2(h5.get(), name, type, space.get(), H5P_DEFAULT, properties.get(), H5P_DEFAULT), H5Dclose);
  ASSERT_TRUE(set.valid()) << name;
  if (!data.empty()) {
    ASSERT_GE(H5Dwrite(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), 0);
  }
}

std::string read_text(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TEST_F(FemImportTest, MalformedXdmfHeavyDataIsRefused) {
  const TetMesh mesh = test::cube_tets(2);
  const auto fresh = [&] { write_tet_mesh(mesh, path("cube.xdmf")); };
  fresh();
  const std::string good = read_text(path("cube.xdmf"));
  const auto refused = [&](const std::string& from, const std::string& to, const std::string& fragment) {
    SCOPED_TRACE(from + " -> " + to);
    expect_refused_text("cube.xdmf", replaced(good, from, to), fragment);
  };
  refused("cube.h5:/Mesh/mesh/topology", "cube.h5:/Mesh/mesh/nothing", "line 7: cube.h5:/Mesh/mesh/nothing: no such dataset");
  refused("Dimensions=\"48 4\"", "Dimensions=\"47 4\"", "the dataset holds 48 x 4 values, its DataItem says 47 x 4");
  refused("cube.h5:/Mesh/mesh/geometry", "other.h5:/Mesh/mesh/geometry",
          "line 10: the HDF5 file " + path("other.h5") + " that holds the data does not exist");

  // Indices and types inside the HDF5 file.
  add_dataset(path("cube.h5"), "/bad_index", H5T_NATIVE_INT64, {48, 4}, std::vector<double>(48 * 4, 99));
  refused("cube.h5:/Mesh/mesh/topology", "cube.h5:/bad_index", "tetrahedron 1 references node 99, but the nodes are numbered 0 to 26");
  add_dataset(path("cube.h5"), "/real_topology", H5T_NATIVE_DOUBLE, {48, 4}, std::vector<double>(48 * 4, 1));
  refused("cube.h5:/Mesh/mesh/topology", "cube.h5:/real_topology", "cube.h5:/real_topology: not integer data");
  // A dataset that announces a billion rows and stores none: refused before any allocation.
  add_dataset(path("cube.h5"), "/lying", H5T_NATIVE_INT64, {1000000000, 4}, {});
  refused("<DataItem Dimensions=\"48 4\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">cube.h5:/Mesh/mesh/topology",
          "<DataItem Dimensions=\"1000000000 4\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">cube.h5:/lying",
          "announces 4000000000 values but stores 0 bytes");
  // A cell tag grid's tet that is not one of the mesh's.
  add_dataset(path("cube.h5"), "/foreign_tet", H5T_NATIVE_INT64, {48, 4}, std::vector<double>(48 * 4, 0));
  refused("cube.h5:/MeshTags/cell_tags/topology", "cube.h5:/foreign_tet", "tagged tetrahedron 1 (points 0, 0, 0, 0) is not a cell of the mesh");

  write_text(path("cube.xdmf"), good);
  write_text(path("cube.h5"), "not HDF5");
  expect_refused("cube.xdmf", path("cube.h5") + " is not an HDF5 file");
  std::filesystem::remove(path("cube.h5"));
  expect_refused("cube.xdmf", "the HDF5 file " + path("cube.h5") + " that holds the data does not exist");
}

// ---- VTU appended data, written here as VTK's own writer lays it out (meshio cannot) ----

std::string base64(const std::string& bytes) {
  static const char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t bits = 0;
    for (std::size_t k = 0; k < 3; ++k)
      bits = (bits << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for (std::size_t k = 0; k < 4; ++k) text += k <= n ? alphabet[(bits >> (18 - 6 * k)) & 63] : '=';
  }
  return text;
}

template <class T>
void append_value(std::string& out, T value, bool big_endian) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if (big_endian) std::reverse(bytes, bytes + sizeof(T));
  out.append(bytes, sizeof(T));
}

struct AppendedLayout {
  bool base64 = false;
  bool zlib = false;
  bool big_endian = false;
  bool header64 = false;
};

// One array's appended block: header and data, base64-encoded as two streams like VTK does. The
// zlib data is cut in 100-byte blocks so that there are several, the last one partial.
std::string appended_block(const std::string& data, const AppendedLayout& layout) {
  std::string header, body;
  const auto put_header = [&](std::uint64_t value) {
    if (layout.header64)
      append_value<std::uint64_t>(header, value, layout.big_endian);
    else
      append_value<std::uint32_t>(header, static_cast<std::uint32_t>(value), layout.big_endian);
  };
  if (!layout.zlib) {
    put_header(data.size());
    body = data;
  } else {
    const std::size_t block = 100;
    const std::size_t blocks = (data.size() + block - 1) / block;
    put_header(blocks);
    put_header(block);
    put_header(data.size() % block);
    for (std::size_t b = 0; b < blocks; ++b) {
      const std::string chunk = data.substr(b * block, block);
      uLongf size = compressBound(static_cast<uLong>(chunk.size()));
      std::string compressed(size, '\0');
      compress(reinterpret_cast<Bytef*>(compressed.data()), &size, reinterpret_cast<const Bytef*>(chunk.data()),
               static_cast<uLong>(chunk.size()));
      compressed.resize(size);
      put_header(compressed.size());
      body += compressed;
    }
  }
  return layout.base64 ? base64(header) + base64(body) : header + body;
}

std::string appended_vtu(const TetMesh& mesh, const AppendedLayout& layout) {
  std::string points, connectivity, offsets, types, regions;
  for (const Vec3& p : mesh.points)
    for (int c = 0; c < 3; ++c) append_value<double>(points, p[c], layout.big_endian);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    for (std::uint32_t v : mesh.tets[t]) append_value<std::int64_t>(connectivity, v, layout.big_endian);
    append_value<std::int64_t>(offsets, static_cast<std::int64_t>(4 * t + 4), layout.big_endian);
    types += static_cast<char>(10);
    append_value<std::int32_t>(regions, mesh.tet_regions[t], layout.big_endian);
  }
  std::string data;
  std::string xml = std::string("<?xml version=\"1.0\"?>\n<!-- written by fem_import_test -->\n") +
                    "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"" +
                    (layout.big_endian ? "BigEndian" : "LittleEndian") + "\" header_type=\"" +
                    (layout.header64 ? "UInt64" : "UInt32") + "\"" +
                    (layout.zlib ? " compressor=\"vtkZLibDataCompressor\"" : "") + ">\n<UnstructuredGrid>\n" +
                    "<Piece NumberOfPoints=\"" + std::to_string(mesh.points.size()) + "\" NumberOfCells=\"" +
                    std::to_string(mesh.tets.size()) + "\">\n";
  const auto array = [&](const char* type, const char* name, const std::string& bytes, const char* extra = "") {
    xml += std::string("<DataArray type=\"") + type + "\" Name=\"" + name + "\"" + extra +
           " format=\"appended\" offset=\"" + std::to_string(data.size()) + "\"/>\n";
    data += appended_block(bytes, layout);
  };
  xml += "<PointData><DataArray type=\"Float64\" Name=\"ignored\" format=\"ascii\">1 2</DataArray></PointData>\n";
  xml += "<CellData Scalars=\"region\">\n";
  array("Int32", "region", regions);
  xml += "</CellData>\n<Points>\n";
  array("Float64", "Points", points, " NumberOfComponents=\"3\"");
  xml += "</Points>\n<Cells>\n";
  array("Int64", "connectivity", connectivity);
  array("Int64", "offsets", offsets);
  array("UInt8", "types", types);
  xml += "</Cells>\n</Piece>\n</UnstructuredGrid>\n";
  return xml + "<AppendedData encoding=\"" + (layout.base64 ? "base64" : "raw") + "\">\n   _" + data +
         "\n</AppendedData>\n</VTKFile>\n";
}

TEST_F(FemImportTest, VtuAppendedDataInEveryLayout) {
  const TetMesh mesh = odd_cube();
  for (int bits = 0; bits < 16; ++bits) {
    const AppendedLayout layout{(bits & 1) != 0, (bits & 2) != 0, (bits & 4) != 0, (bits & 8) != 0};
    const std::string name = "appended" + std::to_string(bits) + ".vtu";
    SCOPED_TRACE(name);
    write_text(path(name), appended_vtu(mesh, layout));
    TetReadReport report;
    const TetMesh read = read_tet_mesh(path(name), &report);
    expect_same_points(mesh, read);
    EXPECT_EQ(read.tets, mesh.tets);
    EXPECT_EQ(read.tet_regions, mesh.tet_regions);
    EXPECT_EQ(report.format, std::string("vtu appended ") + (layout.base64 ? "base64" : "raw") + (layout.zlib ? " zlib" : ""));
  }
}

// ---- small hand-written files ----

// Two tets sharing the face 1 2 3; the second is written with negative volume.
const char* const two_tets_msh22 =
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
    "$PhysicalNames\n1\n3 4 \"solid\"\n$EndPhysicalNames\n"
    "$Nodes\n5\n"
    "1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n"
    "$EndNodes\n"
    "$Elements\n4\n"
    "1 15 2 0 1 1\n"        // a point, skipped
    "2 4 2 4 1 1 2 3 4\n"   // positive
    "3 4 2 4 1 2 4 3 5\n"   // (p4-p2).((p3-p2)x(p5-p2)) < 0
    "4 2 2 9 1 4 3 2\n"     // the shared face: an interface, tag 9
    "$EndElements\n";

// A negative tet among positive ones in its region is not turned over: alone, that would hide a
// tangle (issue 45, item 10). It stays, counted as inverted.
TEST_F(FemImportTest, HandWrittenMsh22WithANegativeTetAmongPositiveOnes) {
  write_text(path("two.msh"), two_tets_msh22);
  TetReadReport report;
  const TetMesh mesh = read_tet_mesh(path("two.msh"), &report);
  EXPECT_EQ(report.format, "msh 2.2 ascii");
  ASSERT_EQ(mesh.tets.size(), 2u);
  EXPECT_EQ(mesh.tets[0], (Tetrahedron{0, 1, 2, 3}));
  EXPECT_EQ(mesh.tets[1], (Tetrahedron{1, 3, 2, 4}));  // as written
  EXPECT_EQ(report.tets_reoriented, 0u);
  EXPECT_EQ(report.tets_inverted, 1u);
  EXPECT_LT(tet_volume(mesh, 1), 0);
  EXPECT_EQ(analyze_tet_quality(mesh).inverted_tets, 1u);
}

// A region whose every tet is negative was written mirrored: its tets are turned over.
TEST_F(FemImportTest, HandWrittenMsh22WithAMirroredRegion) {
  std::string mirrored = two_tets_msh22;
  const std::string positive = "2 4 2 4 1 1 2 3 4\n";
  mirrored.replace(mirrored.find(positive), positive.size(), "2 4 2 4 1 1 3 2 4\n");  // negative too
  write_text(path("two.msh"), mirrored);
  TetReadReport report;
  const TetMesh mesh = read_tet_mesh(path("two.msh"), &report);
  ASSERT_EQ(mesh.tets.size(), 2u);
  EXPECT_EQ(mesh.tets[0], (Tetrahedron{0, 2, 3, 1}));  // corners 2 and 3 swapped
  EXPECT_EQ(mesh.tets[1], (Tetrahedron{1, 3, 4, 2}));
  EXPECT_EQ(report.tets_reoriented, 2u);
  EXPECT_EQ(report.tets_inverted, 0u);
  EXPECT_EQ(report.elements_ignored, 1u);
  EXPECT_EQ(report.interface_faces, 1u);
  EXPECT_EQ(report.internal_faces, 1u);  // both tets in region 4
  EXPECT_EQ(mesh.tet_regions, (std::vector<int>{4, 4}));
  // The interface first (as listed), then the six faces of one tet each, tag 1.
  ASSERT_EQ(mesh.boundary_faces.size(), 7u);
  EXPECT_EQ(mesh.boundary_faces[0], (Face{3, 2, 1}));
  EXPECT_EQ(mesh.boundary_tags, (std::vector<int>{9, 1, 1, 1, 1, 1, 1}));
  for (std::size_t t = 0; t < 2; ++t) EXPECT_GT(tet_volume(mesh, t), 0);
  expect_outward_boundary(mesh);
}

TEST_F(FemImportTest, HandWrittenLegacyVtkWithCellData) {
  write_text(path("one.vtk"),
             "# vtk DataFile Version 2.0\n\nASCII\nDATASET UNSTRUCTURED_GRID\n"
             "POINTS 4 float\n0 0 0  1 0 0  0 1 0  0 0 1\n"
             "CELLS 3 11\n4 0 2 1 3\n3 0 3 1\n1 2\n"
             "CELL_TYPES 3\n10\n5\n1\n"
             "POINT_DATA 4\nVECTORS v double\n0 0 0 0 0 0 0 0 0 0 0 0\n"
             "CELL_DATA 3\nSCALARS other int 1\nLOOKUP_TABLE default\n7 7 7\n"
             "SCALARS CellEntityIds int\nLOOKUP_TABLE default\n2 6 0\n");
  TetReadReport report;
  const TetMesh mesh = read_tet_mesh(path("one.vtk"), &report);
  EXPECT_EQ(report.format, "vtk 2.0 ascii");
  EXPECT_EQ(mesh.tets, (std::vector<Tetrahedron>{{0, 2, 3, 1}}));
  EXPECT_EQ(mesh.tet_regions, (std::vector<int>{2}));
  EXPECT_EQ(report.elements_ignored, 1u);
  ASSERT_EQ(mesh.boundary_faces.size(), 4u);
  EXPECT_EQ(mesh.boundary_faces[0], (Face{0, 1, 3}));  // the triangle 0 3 1 turned outward
  EXPECT_EQ(mesh.boundary_tags, (std::vector<int>{6, 1, 1, 1}));
  expect_outward_boundary(mesh);
}

TEST_F(FemImportTest, HandWrittenMedit) {
  write_text(path("one.mesh"),
             "MeshVersionFormatted 1\n# a comment\nDimension\n3\n"
             "Vertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
             "Edges\n1\n1 2 0\n"
             "Corners\n2\n1 2\n"
             "Triangles\n1\n1 2 3 4\n"
             "Tetrahedra\n1\n1 2 3 4 3\n"
             "End\n");
  TetReadReport report;
  const TetMesh mesh = read_tet_mesh(path("one.mesh"), &report);
  EXPECT_EQ(report.format, "medit 1");
  EXPECT_EQ(report.elements_ignored, 1u);
  EXPECT_EQ(mesh.tet_regions, (std::vector<int>{3}));
  ASSERT_EQ(mesh.boundary_faces.size(), 4u);
  EXPECT_EQ(mesh.boundary_faces[0], (Face{0, 2, 1}));  // 1 2 3 pointed into the tet
  EXPECT_EQ(mesh.boundary_tags[0], 4);
  expect_outward_boundary(mesh);
}

TEST_F(FemImportTest, HandWrittenTetgenOneBasedAndZeroBased) {
  write_text(path("one.node"), "# comment\n5 3 1 1\n1 0 0 0 0.5 1\n2 1 0 0 0.5 1\n3 0 1 0 0.5 1\n4 0 0 1 0.5 1\n"
                               "5 1 1 1 0.5 0\n");
  write_text(path("one.ele"), "2 4 1\n1 1 2 3 4 2\n2 2 3 5 4 -0  # comment\n");
  write_text(path("one.face"), "1 1\n1 1 2 4 8\n");
  TetReadReport report;
  TetMesh mesh = read_tet_mesh(path("one.ele"), &report);
  EXPECT_EQ(report.format, "tetgen 1-based with .face");
  EXPECT_EQ(mesh.tets, (std::vector<Tetrahedron>{{0, 1, 2, 3}, {1, 2, 3, 4}}));  // the second reoriented
  EXPECT_EQ(mesh.tet_regions, (std::vector<int>{2, 1}));
  EXPECT_EQ(mesh.boundary_tags.front(), 8);
  EXPECT_EQ(mesh.boundary_faces.size(), 6u);
  expect_outward_boundary(mesh);

  write_text(path("zero.node"), "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n");
  write_text(path("zero.ele"), "1 4 0\n0 0 1 2 3\n");
  mesh = read_tet_mesh(path("zero.node"), &report);
  EXPECT_EQ(report.format, "tetgen 0-based");
  EXPECT_EQ(mesh.tets, (std::vector<Tetrahedron>{{0, 1, 2, 3}}));
}

// A flat tet is kept as it is (a quality problem, not a format error).
TEST_F(FemImportTest, FlatTetIsKept) {
  write_text(path("flat.mesh"),
             "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n1 1 0 0\n"
             "Tetrahedra\n1\n1 2 3 4 0\nEnd\n");
  const TetMesh mesh = read_tet_mesh(path("flat.mesh"));
  EXPECT_EQ(mesh.tets, (std::vector<Tetrahedron>{{0, 1, 2, 3}}));
  EXPECT_EQ(tet_volume(mesh, 0), 0.0);
  EXPECT_EQ(mesh.tet_regions, (std::vector<int>{1}));
  EXPECT_EQ(mesh.boundary_faces.size(), 4u);
}

// ---- refused files: each an InvalidInput naming the file ----

TEST_F(FemImportTest, MalformedMshIsRefused) {
  const std::string header = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  const std::string nodes = "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n";
  expect_refused_text("truncated.msh", header + "$Nodes\n4\n1 0 0 0\n2 1 0", "truncated");
  expect_refused_text("count.msh", header + "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n",
                      "expected $EndNodes");
  expect_refused_text("range.msh", header + nodes + "$Elements\n1\n1 4 2 0 1 1 2 3 99\n$EndElements\n",
                      "line 13: element 1 references node 99, which $Nodes does not define (4 nodes)");
  expect_refused_text("negative.msh", header + "$Nodes\n-4\n$EndNodes\n", "number of nodes '-4' is negative");
  expect_refused_text("huge.msh", header + "$Nodes\n99999999999999\n1 0 0 0\n$EndNodes\n",
                      "line 7: node number expected, but the section ends ('$EndNodes'): it holds fewer entries than its header announces");
  expect_refused_text("nan.msh", header + "$Nodes\n4\n1 0 0 0\n2 1 nan 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n"
                      "$Elements\n1\n1 4 2 0 1 1 2 3 4\n$EndElements\n", "point #2 has a non-finite coordinate (nan)");
  // A 10-node tet whose mid-edge nodes are its corners.
  expect_refused_text("tet10.msh", header + nodes + "$Elements\n1\n1 11 0 1 2 3 4 1 2 3 4 1 2\n$EndElements\n",
                      "point #1 is a corner and the mid-edge node of tetrahedron #1");
  expect_refused_text("prism.msh", header + nodes + "$Elements\n1\n1 6 0 1 2 3 4 1 2\n$EndElements\n", "6-node prism");
  expect_refused_text("surface.msh", header + nodes + "$Elements\n1\n1 2 0 1 2 3\n$EndElements\n",
                      "no tetrahedra (1 triangles: a surface?");
  expect_refused_text("v40.msh", "$MeshFormat\n4 0 8\n$EndMeshFormat\n", "MSH version '4' is not supported");
  expect_refused_text("negative_region.msh", header + nodes + "$Elements\n1\n1 4 2 -3 1 1 2 3 4\n$EndElements\n",
                      "tetrahedron #1 has region -3");
  expect_refused_text("stray.msh", header + nodes + "$Elements\n2\n1 4 0 1 2 3 4\n2 2 0 1 2 2\n$EndElements\n",
                      "triangle #1 repeats point #2");
  expect_refused_text("twice.msh", header + nodes + "$Elements\n2\n1 4 0 1 2 3 4\n2 4 0 2 1 3 4\n$EndElements\n",
                      "tetrahedra #1 and #2 have the same corners");
  expect_refused_text("empty.msh", "", "empty file");
  expect_refused_text("binary.msh", std::string("$MeshFormat\n4.1 1 8\n\x02\x00\x00\x00\n$EndMeshFormat\n", 37),
                      "the int after the binary header is not 1 in either byte order");
}

// The three tets 0123, 0124, 0125 share the face 0 1 2.
TEST_F(FemImportTest, FaceOfThreeTetsIsRefused) {
  expect_refused_text("three.mesh",
                      "MeshVersionFormatted 2\nDimension 3\nVertices\n6\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
                      "0 0 -1 0\n1 1 1 0\nTetrahedra\n3\n1 2 3 4 1\n1 2 3 5 1\n1 2 3 6 1\nEnd\n",
                      "is shared by 3 tetrahedra (#1 #2 #3)");
}

TEST_F(FemImportTest, MalformedMeditIsRefused) {
  const std::string vertices = "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n";
  expect_refused_text("truncated.mesh", vertices + "Tetrahedra\n2\n1 2 3 4 1\n", "truncated");
  expect_refused_text("range.mesh", vertices + "Tetrahedra\n1\n1 2 3 5 1\nEnd\n",
                      "line 11: tetrahedron 1 references node 5, but the nodes are numbered 1 to 4");
  expect_refused_text("count.mesh", vertices + "Tetrahedra\n1\n1 2 3 4 1\n1 2 3 4 1\nEnd\n", "expected a keyword");
  expect_refused_text("negative.mesh", vertices + "Tetrahedra\n-1\n", "is negative");
  expect_refused_text("huge.mesh", vertices + "Tetrahedra\n4000000000\n1 2 3 4 1\nEnd\n", "is not an integer");
  expect_refused_text("nan.mesh", "MeshVersionFormatted 2\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 nan 0 0\n0 0 1 0\n"
                      "Tetrahedra\n1\n1 2 3 4 1\nEnd\n", "non-finite");
  expect_refused_text("hex.mesh", vertices + "Hexahedra\n1\n1 2 3 4 1 2 3 4 1\nEnd\n", "reads Tetrahedra and TetrahedraP2 only");
  expect_refused_text("2d.mesh", "MeshVersionFormatted 2\nDimension 2\n", "a tetrahedral mesh is 3D");
  expect_refused_text("stray.mesh", vertices + "Triangles\n1\n1 2 3 0\nEnd\n", "no tetrahedra");
  expect_refused_text("notface.mesh",
                      "MeshVersionFormatted 2\nVertices\n5\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n1 1 1 0\n"
                      "Triangles\n1\n1 2 5 0\nTetrahedra\n1\n1 2 3 4 1\nEnd\n",
                      "triangle #1 (points #1, #2, #5) is not a face of any tetrahedron");
}

TEST_F(FemImportTest, MalformedVtkIsRefused) {
  const std::string head = "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                           "POINTS 4 double\n0 0 0 1 0 0 0 1 0 0 0 1\n";
  expect_refused_text("truncated.vtk", head + "CELLS 1 5\n4 0 1 2\n", "truncated");
  expect_refused_text("range.vtk", head + "CELLS 1 5\n4 0 1 2 4\nCELL_TYPES 1\n10\n",
                      "cell 0 references point 4, but the points are 0 to 3");
  expect_refused_text("count.vtk", head + "CELLS 2 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n", "its list holds 1");
  expect_refused_text("negative.vtk", head + "CELLS -1 5\n", "is negative");
  expect_refused_text("huge.vtk", head + "CELLS 1 5000000000\n4 0 1 2 3\nCELL_TYPES 1\n10\n", "is not a number");
  const std::string binary = "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET UNSTRUCTURED_GRID\n";
  expect_refused_text("binary_huge.vtk", binary + "POINTS 4000000000 double\n\x01\x02",
                      "truncated: the file ends inside the POINTS data");
  expect_refused_text("binary_too_many.vtk", binary + "POINTS 5000000000 double\n\x01\x02", "too many points");
  expect_refused_text("hex.vtk", head + "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n12\n", "hexahedron");
  expect_refused_text("polydata.vtk", "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\n",
                      "only UNSTRUCTURED_GRID");
  expect_refused_text("nan.vtk", "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                      "POINTS 4 double\n0 0 0 1 0 0 0 1 0 0 0 inf\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n",
                      "point #4 has a non-finite coordinate (inf)");
}

TEST_F(FemImportTest, MalformedVtuIsRefused) {
  const TetMesh mesh = test::cube_tets(1);
  std::string good = appended_vtu(mesh, {false, true, false, false});  // raw, zlib
  write_text(path("good.vtu"), good);
  ASSERT_NO_THROW(read_tet_mesh(path("good.vtu")));
  const std::size_t data = good.find('_', good.find("<AppendedData")) + 1;
  expect_refused_text("truncated.vtu", good.substr(0, data + 30), "truncated: the file does not end with </VTKFile>");
  std::string lying = good;  // the region array's one block announces a huge compressed size
  lying.replace(data + 12, 4, std::string("\xff\xff\xff\x7f", 4));
  expect_refused_text("lying.vtu", lying, "the data ends before");
  expect_refused_text("polydata.vtu", "<VTKFile type=\"PolyData\">", "only UnstructuredGrid");
  expect_refused_text("lz4.vtu", "<VTKFile type=\"UnstructuredGrid\" compressor=\"vtkLZ4DataCompressor\">",
                      "vtkLZ4DataCompressor");
  const std::string ascii_head = "<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid><Piece NumberOfPoints=\"4\" "
                                 "NumberOfCells=\"1\"><Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" "
                                 "format=\"ascii\">0 0 0 1 0 0 0 1 0 0 0 1</DataArray></Points><Cells>";
  const std::string ascii_tail = "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">4</DataArray>"
                                 "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">10</DataArray></Cells>"
                                 "</Piece></UnstructuredGrid></VTKFile>";
  const auto connectivity = [](const char* ids) {
    return std::string("<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">") + ids + "</DataArray>";
  };
  write_text(path("ascii.vtu"), ascii_head + connectivity("0 1 2 3") + ascii_tail);
  EXPECT_EQ(read_tet_mesh(path("ascii.vtu")).tets.size(), 1u);
  expect_refused_text("range.vtu", ascii_head + connectivity("0 1 2 7") + ascii_tail, "cell 0 references point 7");
  expect_refused_text("count.vtu", ascii_head + connectivity("0 1 2") + ascii_tail, "3 values, but 4 are expected");
  expect_refused_text("base64.vtu",
                      ascii_head + "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"binary\">AAAA*AAA</DataArray>" +
                          ascii_tail,
                      "invalid base64 character '*'");
}

// Two pieces: the second one's point ids count from its own first point.
TEST_F(FemImportTest, VtuPiecesAreJoined) {
  const auto piece = [](const char* points) {
    return std::string("<Piece NumberOfPoints=\"4\" NumberOfCells=\"1\"><Points><DataArray type=\"Float32\" "
                       "NumberOfComponents=\"3\">") + points + "</DataArray></Points><Cells>"
           "<DataArray type=\"Int32\" Name=\"connectivity\">0 1 2 3</DataArray>"
           "<DataArray type=\"Int32\" Name=\"offsets\">4</DataArray>"
           "<DataArray type=\"UInt8\" Name=\"types\">10</DataArray></Cells></Piece>";
  };
  write_text(path("pieces.vtu"), "<VTKFile type='UnstructuredGrid'><UnstructuredGrid>" + piece("0 0 0 1 0 0 0 1 0 0 0 1") +
                                     piece("5 0 0 6 0 0 5 1 0 5 0 1") + "</UnstructuredGrid></VTKFile>");
  const TetMesh mesh = read_tet_mesh(path("pieces.vtu"));
  EXPECT_EQ(mesh.points.size(), 8u);
  EXPECT_EQ(mesh.tets, (std::vector<Tetrahedron>{{0, 1, 2, 3}, {4, 5, 6, 7}}));
  EXPECT_EQ(mesh.boundary_faces.size(), 8u);
}

TEST_F(FemImportTest, MalformedTetgenIsRefused) {
  const std::string node = "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";
  const std::string ele = "1 4 0\n1 1 2 3 4\n";
  write_text(path("a.node"), node);
  expect_refused_text("a.ele", "1 4 0\n1 1 2 3 5\n",
                      "line 2: tetrahedron 1 references node 5, but the nodes are numbered 1 to 4");
  expect_refused_text("a.ele", "2 4 0\n1 1 2 3 4\n", "truncated");
  expect_refused_text("a.ele", "1 10 0\n1 1 2 3 4 1 2 3 4 1 2\n", "10 nodes per tetrahedron");
  expect_refused_text("a.ele", "-1 4 0\n", "is negative");
  expect_refused_text("a.ele", "1 4 1\n1 1 2 3 4 1.5\n", "line 2: region attribute 1.5 is not an integer");
  expect_refused_text("a.ele", "1 4 0\n3 1 2 3 4\n", "the first item is numbered 3");
  write_text(path("a.ele"), ele);
  expect_refused_text("a.face", "1 1\n1 1 2 3\n", "boundary marker missing", "a.node");
  std::filesystem::remove(path("a.face"));
  expect_refused_text("a.node", "4000000000 3 0 0\n1 0 0 0\n", "truncated");
  expect_refused_text("a.node", "2 3 0 0\n1 0 0 0\n3 1 0 0\n", "item numbered 3, expected 2");
  expect_refused_text("a.node", "4 2 0 0\n", "a tetrahedral mesh is 3D");
  expect_refused_text("a.node", "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 -nan\n", "non-finite");
  // The mesh as a whole is named by the path given.
  write_text(path("a.node"), node);
  write_text(path("a.face"), "1 1\n1 1 2 3 -2\n");
  expect_refused("a.ele", "triangle #1 has tag -2");
  std::filesystem::remove(path("a.ele"));
  EXPECT_THROW(read_tet_mesh(path("a.node")), IoError);
}

TEST_F(FemImportTest, UnknownExtensionAndMissingFile) {
  try {
    read_tet_mesh(path("m.inp"));
    ADD_FAILURE() << "no exception";
  } catch (const InvalidInput& e) {
    const std::string message = e.what();
    for (const char* extension : {".msh", ".vtu", ".vtk", ".mesh", ".node", ".ele", ".xdmf"})
      EXPECT_NE(message.find(extension), std::string::npos) << message;
  }
  EXPECT_THROW(read_tet_mesh(path("missing.msh")), IoError);
  EXPECT_TRUE(is_tet_mesh_path("a/B.VTU"));
  EXPECT_TRUE(is_tet_mesh_path("a/B.XDMF"));
  EXPECT_FALSE(is_tet_mesh_path("a/b.off"));
}

}  // namespace
}  // namespace meshprep
