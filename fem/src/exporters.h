#pragma once
// The per-format tetrahedral mesh writers behind write_tet_mesh (export.cpp), and the helpers
// they share. Each writer receives a mesh that write_tet_mesh has already validated (sizes agree,
// indices in range, tags >= 1, finite coordinates) and writes through write_file_atomically.

#include "meshprep/fem/export.h"

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

}  // namespace meshprep::detail
