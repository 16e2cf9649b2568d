// write_tet_mesh: validates the mesh once, then dispatches on the extension to a writer in
// export_<format>.cpp.
#include "meshprep/fem/export.h"

#include "exporters.h"
#include "vtu_files.h"
#include "meshprep/core/errors.h"
#include "meshprep/core/patch_names.h"
#include "meshprep/fem/tet_quality.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <filesystem>
#include <limits>

namespace meshprep {
namespace {

using Writer = void (*)(const TetMesh&, const std::string&, const TetExportOptions&);
// A writer that may have to round coordinates to fit the format (.inp), and reports it.
using RoundingWriter = void (*)(const TetMesh&, const std::string&, TetExportReport&);

struct Format {
  const char* extension;
  const char* name;         // for messages
  bool binary, ascii;       // whether it can store numbers in binary, in ASCII
  Writer write = nullptr;
  RoundingWriter write_rounding = nullptr;  // instead of write
};

const std::array<Format, 7> formats{{
    {".msh", "Gmsh", true, true,
     [](const TetMesh& m, const std::string& p, const TetExportOptions& o) { detail::write_gmsh(m, p, o); }},
    {".vtu", "VTK XML", true, true,
     [](const TetMesh& m, const std::string& p, const TetExportOptions& o) { detail::write_vtu(m, p, o); }},
    {".vtk", "VTK legacy", false, true,
     [](const TetMesh& m, const std::string& p, const TetExportOptions&) { detail::write_vtk_legacy(m, p); }},
    {".mesh", "Medit", false, true,
     [](const TetMesh& m, const std::string& p, const TetExportOptions&) { detail::write_medit(m, p); }},
    {".node", "TetGen", false, true,
     [](const TetMesh& m, const std::string& p, const TetExportOptions&) { detail::write_tetgen(m, p); }},
    {".inp", "Abaqus/CalculiX", false, true, nullptr,
     [](const TetMesh& m, const std::string& p, TetExportReport& r) { detail::write_abaqus(m, p, r); }},
    {".xdmf", "XDMF + HDF5", true, false,
     [](const TetMesh& m, const std::string& p, const TetExportOptions&) { detail::write_xdmf(m, p); }},
}};

// The extensions of the formats that can store numbers as asked ("binary" or "ascii").
std::string formats_that_can(bool Format::*can) {
  std::string list;
  for (const Format& format : formats)
    if (format.*can) list += std::string(list.empty() ? "" : " ") + format.extension;
  return list;
}

std::string lowercase_extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

const Format& format_for(const std::string& path) {
  const std::string extension = lowercase_extension(path);
  for (const Format& format : formats)
    if (extension == format.extension) return format;
  std::string supported;
  for (const Format& format : formats) supported += std::string(supported.empty() ? "" : ", ") + format.extension;
  throw InvalidInput(path + ": unknown tetrahedral mesh format '" + extension + "' (supported: " + supported + ")");
}

template <std::size_t N>
void check_indices(const std::string& path, const char* what, std::size_t element,
                   const std::array<std::uint32_t, N>& vertices, std::size_t num_points) {
  for (std::size_t i = 0; i < N; ++i) {
    if (vertices[i] >= num_points)
      throw InvalidInput(path + ": cannot export: " + what + " " + std::to_string(element) + " has vertex index " +
                         std::to_string(vertices[i]) + " but the mesh has " + std::to_string(num_points) + " points");
    for (std::size_t j = 0; j < i; ++j)
      if (vertices[i] == vertices[j])
        throw InvalidInput(path + ": cannot export: " + what + " " + std::to_string(element) + " repeats vertex " +
                           std::to_string(vertices[i]));
  }
}

void check_tags(const std::string& path, const char* what, const std::vector<int>& tags) {
  const auto bad = std::find_if(tags.begin(), tags.end(), [](int tag) { return tag < 1; });
  if (bad != tags.end())
    throw InvalidInput(path + ": cannot export: " + what + " " + std::to_string(*bad) + " (must be >= 1)");
}

// A second-order mesh's mid-edge nodes: one row per tet, in range, no corner among them, and
// every boundary face a face of a tet (its nodes are that tet's).
void validate_second_order(const TetMesh& mesh, const std::string& path) {
  if (mesh.tet_edge_nodes.size() != mesh.tets.size())
    throw InvalidInput(path + ": cannot export: " + std::to_string(mesh.tets.size()) + " tets but " +
                       std::to_string(mesh.tet_edge_nodes.size()) + " rows of mid-edge nodes");
  std::vector<bool> corner(mesh.points.size(), false);
  for (const Tetrahedron& t : mesh.tets)
    for (const std::uint32_t v : t) corner[v] = true;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    check_indices(path, "tet mid-edge node row", t, mesh.tet_edge_nodes[t], mesh.points.size());
    for (const std::uint32_t v : mesh.tet_edge_nodes[t])
      if (corner[v])
        throw InvalidInput(path + ": cannot export: point " + std::to_string(v) +
                           " is a tet's corner and the mid-edge node of tet " + std::to_string(t));
  }
  try {
    boundary_face_edge_nodes(mesh);
  } catch (const InvalidInput& e) {
    throw InvalidInput(path + ": cannot export: " + e.what());
  }
}

// Structural checks only: orientation is the TetMesh invariant (tets positive, faces outward).
void validate(const TetMesh& mesh, const std::string& path) {
  if (mesh.tets.empty()) throw InvalidInput(path + ": cannot export: the mesh has no tetrahedra");
  if (mesh.tets.size() != mesh.tet_regions.size())
    throw InvalidInput(path + ": cannot export: " + std::to_string(mesh.tets.size()) + " tets but " +
                       std::to_string(mesh.tet_regions.size()) + " tet regions");
  if (mesh.boundary_faces.size() != mesh.boundary_tags.size())
    throw InvalidInput(path + ": cannot export: " + std::to_string(mesh.boundary_faces.size()) +
                       " boundary faces but " + std::to_string(mesh.boundary_tags.size()) + " boundary tags");
  // Every format numbers nodes and elements with (at most) 32-bit signed integers.
  constexpr auto max_id = static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max());
  if (mesh.points.size() >= max_id || mesh.tets.size() + mesh.boundary_faces.size() >= max_id)
    throw InvalidInput(path + ": cannot export: too many points or elements for 32-bit ids");
  for (std::size_t p = 0; p < mesh.points.size(); ++p)
    if (!mesh.points[p].allFinite())
      throw InvalidInput(path + ": cannot export: point " + std::to_string(p) + " has a non-finite coordinate");
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) check_indices(path, "tet", t, mesh.tets[t], mesh.points.size());
  for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f)
    check_indices(path, "boundary face", f, mesh.boundary_faces[f], mesh.points.size());
  if (const std::string flat = describe_flat_tets(mesh); !flat.empty())
    throw InvalidInput(path + ": cannot export: " + flat + "; a solver cannot take such tets");
  if (mesh.quadratic()) validate_second_order(mesh, path);
  check_tags(path, "tet region", mesh.tet_regions);
  check_tags(path, "boundary tag", mesh.boundary_tags);
  for (const TagNames* names : {&mesh.region_names, &mesh.boundary_names})
    for (const auto& [tag, name] : *names)
      if (!is_valid_name(name)) throw InvalidInput(path + ": cannot export the name '" + name + "': " + kNameRule);
}

}  // namespace

namespace detail {

void write_real(std::ostream& out, double value) {
  std::array<char, 32> buffer;  // the longest shortest-round-trip double is 24 characters
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  out.write(buffer.data(), result.ptr - buffer.data());
}

void write_point(std::ostream& out, const Vec3& p, const char* separator) {
  write_real(out, p.x());
  out << separator;
  write_real(out, p.y());
  out << separator;
  write_real(out, p.z());
}

std::vector<int> distinct_tags(const std::vector<int>& tags) {
  std::vector<int> distinct = tags;
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  return distinct;
}

}  // namespace detail

std::vector<std::string> tet_mesh_files(const std::string& path) {
  const std::string extension = lowercase_extension(path);
  const auto sibling = [&](const char* other) { return std::filesystem::path(path).replace_extension(other).string(); };
  if (extension == ".node") return {path, sibling(".ele"), sibling(".face")};
  if (extension == ".xdmf") return {path, sibling(".h5")};
  if (extension == ".vtu") return {path, detail::vtu_boundary_path(path)};
  return {path};
}

void check_tet_export_options(const std::string& path, const TetExportOptions& options) {
  const Format& format = format_for(path);
  if (options.binary && options.ascii) throw InvalidInput(path + ": cannot be written both binary and ASCII");
  if (options.binary && !format.binary)
    throw InvalidInput(path + ": cannot write " + format.name + " (" + format.extension +
                       ") binary: it is a text format (binary: " + formats_that_can(&Format::binary) + ")");
  if (options.ascii && !format.ascii)
    throw InvalidInput(path + ": cannot write " + format.name + " (" + format.extension +
                       ") as ASCII: its data is binary (ASCII: " + formats_that_can(&Format::ascii) + ")");
}

void write_tet_mesh(const TetMesh& mesh, const std::string& path, const TetExportOptions& options,
                    TetExportReport* report) {
  const Format& format = format_for(path);
  check_tet_export_options(path, options);
  validate(mesh, path);
  TetExportReport written;
  if (format.write_rounding)
    format.write_rounding(mesh, path, written);
  else
    format.write(mesh, path, options);
  if (report) *report = written;
}

}  // namespace meshprep
