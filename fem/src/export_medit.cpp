// Medit / Gamma Mesh Format ASCII .mesh (libMeshb, https://github.com/LoicMarechal/libMeshb):
// "MeshVersionFormatted 2" (double precision), 1-based vertex numbers, each entity followed by
// an integer reference: 0 on vertices, the boundary tag on triangles, the region on tetrahedra.
//
// Orientation: the same as Gmsh's, i.e. positive volume in TetMesh's sense (Mmg, the main consumer
// of .mesh volume meshes, reorders any tetrahedron with (p1-p0).((p2-p0)x(p3-p0)) < 0 on input);
// triangles keep their outward orientation.
//
// Second order: TrianglesP2 (3 corners, then the nodes of (0,1) (1,2) (2,0)) and TetrahedraP2 (4
// corners, then the nodes of kTetEdges, VTK's order), each followed by its reference: what Gmsh
// writes for `gmsh -3 -order 2 -o x.mesh` (checked on a box), libMeshb's keywords 24 and 30.
#include "exporters.h"

#include "meshprep/core/atomic_file.h"

#include <array>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace meshprep::detail {
namespace {

template <std::size_t N>
void write_section(std::ostream& out, const char* keyword, const std::vector<std::array<std::uint32_t, N>>& elements,
                   const std::vector<int>& references) {
  if (elements.empty()) return;
  out << keyword << '\n' << elements.size() << '\n';
  for (std::size_t e = 0; e < elements.size(); ++e) {
    for (std::uint32_t v : elements[e]) out << v + std::size_t{1} << ' ';
    out << references[e] << '\n';
  }
}

void write_medit_stream(std::ostream& out, const TetMesh& mesh) {
  out << "MeshVersionFormatted 2\n"
      << "Dimension 3\n"
      << "Vertices\n"
      << mesh.points.size() << '\n';
  for (const Vec3& p : mesh.points) {
    write_point(out, p);
    out << " 0\n";
  }
  if (mesh.quadratic()) {
    write_section(out, "TrianglesP2", with_nodes(mesh.boundary_faces, boundary_face_edge_nodes(mesh)), mesh.boundary_tags);
    write_section(out, "TetrahedraP2", with_nodes(mesh.tets, mesh.tet_edge_nodes), mesh.tet_regions);
  } else {
    write_section(out, "Triangles", mesh.boundary_faces, mesh.boundary_tags);
    write_section(out, "Tetrahedra", mesh.tets, mesh.tet_regions);
  }
  out << "End\n";
}

}  // namespace

void write_medit(const TetMesh& mesh, const std::string& path) {
  write_file_atomically(path, [&](std::ostream& out) { write_medit_stream(out, mesh); });
}

}  // namespace meshprep::detail
