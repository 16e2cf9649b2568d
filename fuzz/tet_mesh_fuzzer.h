#pragma once
/// \file tet_mesh_fuzzer.h
/// The body of the tet mesh reader targets: read_tet_mesh on the bytes in memory, and the checks of
/// what import.h promises of a mesh it returns.

#include "fuzz_support.h"
#include "importers.h"

#include <algorithm>
#include <map>

namespace meshprep::fuzz {

/// What import.h promises: tets, finite points, indices in range, positive (or flat) tets but for
/// those the report counts as inverted (a tangle), tags >= 1, and every face of exactly one tet
/// among the boundary faces.
inline void require_valid_tet_mesh(const TetMesh& mesh, const TetReadReport& report) {
  require(!mesh.tets.empty(), "a mesh that was read has tets");
  require(mesh.tet_regions.size() == mesh.tets.size(), "one region per tet");
  require(mesh.boundary_tags.size() == mesh.boundary_faces.size(), "one tag per boundary face");
  for (const Vec3& p : mesh.points) require(p.allFinite(), "every point is finite");
  std::size_t negative = 0;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    for (const std::uint32_t corner : mesh.tets[t]) require(corner < mesh.points.size(), "every corner indexes a point");
    // Not >= 0: coordinates near the double range may make a volume overflow to NaN.
    negative += tet_volume(mesh, t) < 0;
  }
  require(negative == report.tets_inverted, "the tets of negative volume are those the report counts as inverted");
  for (const int region : mesh.tet_regions) require(region >= 1, "regions are >= 1");
  for (const int tag : mesh.boundary_tags) require(tag >= 1, "boundary tags are >= 1");
  std::map<Triangle, int> faces;  // sorted corners -> tets
  for (const Tetrahedron& t : mesh.tets)
    for (int k = 0; k < 4; ++k) {
      Triangle f{t[(k + 1) % 4], t[(k + 2) % 4], t[(k + 3) % 4]};
      std::sort(f.begin(), f.end());
      require(++faces[f] <= 2, "no face has more than two tets");
    }
  std::map<Triangle, int> listed;
  for (Triangle f : mesh.boundary_faces) {
    for (const std::uint32_t corner : f) require(corner < mesh.points.size(), "every boundary corner indexes a point");
    std::sort(f.begin(), f.end());
    require(faces.count(f) == 1, "every boundary face is a face of a tet");
    require(++listed[f] == 1, "no boundary face is listed twice");
  }
  for (const auto& [face, tets] : faces)
    if (tets == 1) require(listed.count(face) == 1, "every face of one tet is a boundary face");
}

/// Reads the bytes as a file of the given format would be read.
inline int fuzz_tet_mesh_reader(detail::TetFormat format, const char* name, const std::uint8_t* data, std::size_t size) {
  refuse_only_with_meshprep_errors([&] {
    TetReadReport report;
    const TetMesh mesh = detail::read_tet_mesh_from_bytes(as_text(data, size), format, name, &report);
    require_valid_tet_mesh(mesh, report);
  });
  return 0;
}

}  // namespace meshprep::fuzz
