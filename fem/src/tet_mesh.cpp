#include "meshprep/fem/tet_mesh.h"

#include "tet_faces.h"

#include "meshprep/core/errors.h"

#include <string>
#include <vector>

namespace meshprep {

double tet_volume(const TetMesh& mesh, std::size_t t) {
  const auto& v = mesh.tets[t];
  const Vec3& p0 = mesh.points[v[0]];
  return (mesh.points[v[1]] - p0).dot((mesh.points[v[2]] - p0).cross(mesh.points[v[3]] - p0)) / 6.0;
}

int tet_edge_index(const Tetrahedron& tet, std::uint32_t a, std::uint32_t b) {
  for (int e = 0; e < 6; ++e) {
    const std::uint32_t u = tet[kTetEdges[e][0]], v = tet[kTetEdges[e][1]];
    if ((u == a && v == b) || (u == b && v == a)) return e;
  }
  return -1;
}

std::array<std::uint32_t, 3> face_edge_nodes(const Tetrahedron& tet, const TetEdgeNodes& nodes, const Triangle& face) {
  std::array<std::uint32_t, 3> mid{};
  for (int k = 0; k < 3; ++k) mid[k] = nodes[tet_edge_index(tet, face[k], face[(k + 1) % 3])];
  return mid;
}

std::vector<std::array<std::uint32_t, 3>> boundary_face_edge_nodes(const TetMesh& mesh) {
  std::vector<std::array<std::uint32_t, 3>> mid;
  if (!mesh.quadratic()) return mid;
  if (mesh.tet_edge_nodes.size() != mesh.tets.size())
    throw InvalidInput("tet mesh: " + std::to_string(mesh.tet_edge_nodes.size()) + " rows of mid-edge nodes for " +
                       std::to_string(mesh.tets.size()) + " tets");
  const std::vector<std::uint32_t> tet_faces = detail::tet_faces_of(mesh.tets, mesh.boundary_faces);
  mid.reserve(mesh.boundary_faces.size());
  for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f) {
    if (tet_faces[f] == detail::kNoTetFace)
      throw InvalidInput("tet mesh: boundary face " + std::to_string(f) + " is no face of any tet");
    const std::size_t t = tet_faces[f] / 4;
    mid.push_back(face_edge_nodes(mesh.tets[t], mesh.tet_edge_nodes[t], mesh.boundary_faces[f]));
  }
  return mid;
}

TetMesh linear_mesh(const TetMesh& mesh) {
  TetMesh linear = mesh;
  linear.tet_edge_nodes.clear();
  if (!mesh.quadratic()) return linear;
  constexpr std::uint32_t kUnused = ~std::uint32_t(0);
  std::vector<std::uint32_t> index(mesh.points.size(), kUnused);
  for (const Tetrahedron& t : mesh.tets)
    for (const std::uint32_t v : t) index[v] = 0;
  for (const Triangle& f : mesh.boundary_faces)
    for (const std::uint32_t v : f) index[v] = 0;
  linear.points.clear();
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    if (index[v] != kUnused) {
      index[v] = static_cast<std::uint32_t>(linear.points.size());
      linear.points.push_back(mesh.points[v]);
    }
  for (Tetrahedron& t : linear.tets)
    for (std::uint32_t& v : t) v = index[v];
  for (Triangle& f : linear.boundary_faces)
    for (std::uint32_t& v : f) v = index[v];
  return linear;
}

}  // namespace meshprep
