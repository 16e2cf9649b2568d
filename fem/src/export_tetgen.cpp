// TetGen .node/.ele/.face (TetGen 1.5 manual, section 5.2; https://wias-berlin.de/software/tetgen/
// fformats.html), 1-based:
//   .node  "<#points> 3 0 0", then "<i> <x> <y> <z>"
//   .ele   "<#tets> 4 1",     then "<i> <n1> <n2> <n3> <n4> <region>"
//   .face  "<#faces> 1",      then "<i> <n1> <n2> <n3> <boundary tag>"
// Comments are only written before the first line: some readers (meshio) skip '#' lines only there.
// Linear tets only: a second-order mesh is refused (TetGen's own 10-node .ele, from -o2, lists
// its mid-edge nodes in an order of its own, which neither this writer nor our reader handles).
//
// Orientation: TetGen itself outputs tets with (p1-p0).((p2-p0)x(p3-p0)) > 0 (checked on
// libtet 1.5), TetMesh's convention, so tets are written in their own order; faces stay outward.
#include "exporters.h"

#include "meshprep/core/atomic_file.h"
#include "meshprep/core/errors.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace meshprep::detail {
namespace {

const char* const comment = "# written by meshprep\n";

void write_node_file(std::ostream& out, const TetMesh& mesh) {
  out << comment << mesh.points.size() << " 3 0 0\n";
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    out << v + 1 << ' ';
    write_point(out, mesh.points[v]);
    out << '\n';
  }
}

template <std::size_t N>
void write_elements(std::ostream& out, const std::vector<std::array<std::uint32_t, N>>& elements,
                    const std::vector<int>& tags) {
  for (std::size_t e = 0; e < elements.size(); ++e) {
    out << e + 1;
    for (std::uint32_t v : elements[e]) out << ' ' << v + std::size_t{1};
    out << ' ' << tags[e] << '\n';
  }
}

std::string sibling(const std::string& path, const char* extension) {
  return std::filesystem::path(path).replace_extension(extension).string();
}

}  // namespace

// The three writes are nested so that all three temporary files are complete before the first
// rename (.face, then .ele, then .node): a failure while writing leaves no new file behind.
void write_tetgen(const TetMesh& mesh, const std::string& path) {
  if (mesh.quadratic())
    throw InvalidInput(path + ": cannot export a second-order mesh as TetGen .node/.ele: meshprep writes "
                              "them with linear tets only (write .msh, .vtk, .vtu, .mesh, .inp or .xdmf)");
  write_file_atomically(path, [&](std::ostream& node_out) {
    write_node_file(node_out, mesh);
    node_out.flush();
    write_file_atomically(sibling(path, ".ele"), [&](std::ostream& ele_out) {
      ele_out << comment << mesh.tets.size() << " 4 1\n";
      write_elements(ele_out, mesh.tets, mesh.tet_regions);
      ele_out.flush();
      write_file_atomically(sibling(path, ".face"), [&](std::ostream& face_out) {
        face_out << comment << mesh.boundary_faces.size() << " 1\n";
        write_elements(face_out, mesh.boundary_faces, mesh.boundary_tags);
      });
    });
  });
}

}  // namespace meshprep::detail
