#pragma once
// The per-format tetrahedral mesh writers behind write_tet_mesh (export.cpp), and the helpers
// they share. Each writer receives a mesh that write_tet_mesh has already validated (sizes agree,
// indices in range, tags >= 1, finite coordinates) and writes through write_file_atomically.

#include "meshprep/fem/export.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace meshprep::detail {

void write_gmsh(const TetMesh& mesh, const std::string& path, const TetExportOptions& options);
void write_vtu(const TetMesh& mesh, const std::string& path, const TetExportOptions& options);
void write_vtk_legacy(const TetMesh& mesh, const std::string& path);
void write_medit(const TetMesh& mesh, const std::string& path);
void write_tetgen(const TetMesh& mesh, const std::string& path);
void write_abaqus(const TetMesh& mesh, const std::string& path, TetExportReport& report);
void write_xdmf(const TetMesh& mesh, const std::string& path);

/// Writes `value` in the shortest form that reads back to the same double (std::to_chars).
void write_real(std::ostream& out, double value);

/// Writes the three coordinates of `p` separated by `separator`.
void write_point(std::ostream& out, const Vec3& p, const char* separator = " ");

/// The distinct values of `tags`, ascending (the regions or boundary tags present in a mesh).
std::vector<int> distinct_tags(const std::vector<int>& tags);

/// Second-order elements as most formats list them: each element's corners, then its mid-edge
/// nodes (`nodes`, one row per element).
template <std::size_t N, std::size_t M>
std::vector<std::array<std::uint32_t, N + M>> with_nodes(const std::vector<std::array<std::uint32_t, N>>& corners,
                                                         const std::vector<std::array<std::uint32_t, M>>& nodes) {
  std::vector<std::array<std::uint32_t, N + M>> elements(corners.size());
  for (std::size_t e = 0; e < corners.size(); ++e) {
    std::copy(corners[e].begin(), corners[e].end(), elements[e].begin());
    std::copy(nodes[e].begin(), nodes[e].end(), elements[e].begin() + N);
  }
  return elements;
}

}  // namespace meshprep::detail
