// Format dispatch by extension: read_soup (and parse_soup, from memory), load_mesh, write_mesh, extension_of;
// require_all_faces.
#include "meshprep/core/io.h"

#include "readers.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace meshprep {
namespace {

detail::SoupReader reader_for(const std::string& path, const std::string& extension) {
  if (extension == "off") return &detail::read_off;
  if (extension == "obj") return &detail::read_obj;
  if (extension == "ply") return &detail::read_ply;
  if (extension == "stl") return &detail::read_stl;
  detail::fail(path, detail::unknown_extension_problem(extension));
}

TriangleSoup parse_with(detail::SoupReader reader, const std::string& path, std::string_view data,
                        ReadReport* report) {
  if (data.empty()) detail::fail(path, "empty file");
  ReadReport read;
  read.path = path;
  TriangleSoup soup = reader(path, data, read);
  if (soup.triangles.empty()) detail::fail(path, "no faces");
  detail::check_extent(path, soup.points);
  read.triangles = soup.triangles.size();
  if (report) *report = read;
  return soup;
}

}  // namespace

std::string extension_of(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  if (!extension.empty()) extension.erase(0, 1);  // the dot
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

TriangleSoup detail::parse_soup(const std::string& path, std::string_view data, ReadReport* report) {
  return parse_with(reader_for(path, extension_of(path)), path, data, report);
}

TriangleSoup read_soup(const std::string& path, ReadReport* report) {
  const detail::SoupReader reader = reader_for(path, extension_of(path));  // an unknown extension before a missing file
  return parse_with(reader, path, read_input_file(path), report);
}

LoadedMesh load_mesh(const std::string& path) {
  LoadedMesh loaded;
  loaded.soup = read_soup(path, &loaded.read);
  loaded.mesh = mesh_from_soup(loaded.soup, &loaded.build);
  return loaded;
}

void require_all_faces(const LoadedMesh& loaded, const std::string& stage) {
  if (!loaded.build.dropped_faces.empty())
    detail::fail(loaded.read.path, dropped_faces_problem(loaded.soup, loaded.build) + "; " + stage +
                                       " needs a manifold, consistently oriented surface (meshprep quality lists "
                                       "the faces)");
  const auto has_area = [&](const Triangle& t) {
    const std::vector<Vec3>& p = loaded.soup.points;
    return (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]).squaredNorm() > 0;
  };
  if (std::none_of(loaded.soup.triangles.begin(), loaded.soup.triangles.end(), has_area))
    detail::fail(loaded.read.path, "no face has a positive area; " + stage + " needs a surface");
}

void write_mesh(const TriMesh& mesh, const std::string& path, const WriteOptions& options) {
  write_soup(soup_from_mesh(mesh), path, options);
}

}  // namespace meshprep
