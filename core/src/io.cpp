// Format dispatch by extension: read_soup (and parse_soup, from memory), load_mesh, write_mesh, extension_of,
// is_surface_mesh_path;
// require_all_faces.
#include "meshprep/core/io.h"

#include "readers.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>

namespace meshprep {
namespace {

struct SurfaceFormat {
  const char* extension;
  detail::SoupReader reader;
};

// The surface formats, each read by its reader (readers.h).
constexpr SurfaceFormat kSurfaceFormats[] = {
    {"off", &detail::read_off}, {"obj", &detail::read_obj}, {"ply", &detail::read_ply}, {"stl", &detail::read_stl}};

const SurfaceFormat* surface_format(const std::string& extension) {
  for (const SurfaceFormat& format : kSurfaceFormats)
    if (extension == format.extension) return &format;
  return nullptr;
}

detail::SoupReader reader_for(const std::string& path, const std::string& extension) {
  detail::refuse_folder(path);
  if (const SurfaceFormat* format = surface_format(extension)) return format->reader;
  detail::fail(path, detail::unknown_extension_problem(extension));
}

// The file's groups made the soup's patches (io.h): faces outside any group (0) join "default",
// a tag the file names without faces is no patch, a single group is dropped (the part's name),
// names are made to follow the rule. A reader's tags are kept (PLY's are the file's own values).
void settle_patches(TriangleSoup& soup, ReadReport& read) {
  if (soup.patches.empty()) {
    soup.patch_names.clear();
    return;
  }
  soup.patches.resize(soup.triangles.size(), 0);
  std::map<int, std::size_t> faces;
  for (const int patch : soup.patches) ++faces[patch];
  TagNames names;
  for (const auto& [tag, count] : faces)
    if (tag != 0) names[tag] = soup.patch_names.count(tag) ? soup.patch_names.at(tag) : "patch_" + std::to_string(tag);
  if (faces.count(0)) {
    const int fresh = names.empty() ? 1 : names.rbegin()->first + 1;
    names[fresh] = "default";
    std::replace(soup.patches.begin(), soup.patches.end(), 0, fresh);
  }
  if (names.size() < 2) {
    soup.patches.clear();
    soup.patch_names.clear();
    read.patches_from.clear();
    return;
  }
  read.renamed_patches = sanitize_names(names);
  soup.patch_names = std::move(names);
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
  settle_patches(soup, read);
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

bool is_surface_mesh_path(const std::string& path) { return surface_format(extension_of(path)) != nullptr; }

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
