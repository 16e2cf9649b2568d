#pragma once
// The two files of a tet mesh in VTK XML: export_vtu.cpp writes x.vtu (the tets) and beside it
// x_boundary.vtu (the boundary faces, tags and names); import_vtu.cpp reads both.

#include <filesystem>
#include <string>

namespace meshprep::detail {

/// "dir/x.vtu" -> "dir/x_boundary.vtu".
inline std::string vtu_boundary_path(const std::string& path) {
  const std::filesystem::path p(path);
  return (p.parent_path() / (p.stem().string() + "_boundary" + p.extension().string())).string();
}

}  // namespace meshprep::detail
