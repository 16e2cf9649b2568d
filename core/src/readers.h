#pragma once
/// \file readers.h
/// The per-format soup readers behind read_soup, and the helpers they share.

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "meshprep/core/io.h"

namespace meshprep::detail {

/// A format reader: parses `data` (the whole content of `path`, not empty) into a soup, sets
/// report.format and counts faces in `report` (through add_polygon). Throws InvalidInput.
using SoupReader = TriangleSoup (*)(const std::string& path, std::string_view data, ReadReport& report);

TriangleSoup read_off(const std::string& path, std::string_view data, ReadReport& report);
TriangleSoup read_obj(const std::string& path, std::string_view data, ReadReport& report);
TriangleSoup read_ply(const std::string& path, std::string_view data, ReadReport& report);
TriangleSoup read_stl(const std::string& path, std::string_view data, ReadReport& report);

/// read_soup on content already in memory: the extension of `path` chooses the format and `path`
/// names the input in messages; nothing touches the disk (the fuzz targets in fuzz/ call this).
TriangleSoup parse_soup(const std::string& path, std::string_view data, ReadReport* report = nullptr);

/// read_points on content already in memory, likewise.
PointSet parse_points(const std::string& path, std::string_view data);

/// Throws InvalidInput with the one-line message "<path>: <problem>".
[[noreturn]] void fail(const std::string& path, const std::string& problem);

/// Refuses a folder given where a file is read ("<path>: a folder, not a mesh file ...").
void refuse_folder(const std::string& path);

/// The problem with a mesh path whose extension is not off, obj, ply or stl (for readers and writers).
std::string unknown_extension_problem(const std::string& extension);

/// "line <n>: ", the prefix of problems found on a text line.
std::string at_line(std::size_t line);

/// Whether all three coordinates are finite.
bool is_finite(const Vec3& p);

/// The first non-finite coordinate of `p` as text ("nan", "inf" or "-inf").
std::string non_finite_text(const Vec3& p);

/// Refuses points whose extent along an axis exceeds the largest the stages compute with
/// (largest_extent, reader_support.cpp), or overflows: InvalidInput "<path>: the coordinates span
/// <extent> along x, more than ..."; and points whose whole extent is not zero but below the
/// smallest (smallest_extent): "<path>: the coordinates span only ...". Every reader calls this on
/// what it read.
void check_extent(const std::string& path, const std::vector<Vec3>& points);

/// How many of `announced` items to reserve memory for when each takes at least
/// `min_bytes_each` of the `bytes` left in the file: a lying header cannot make us allocate more
/// than the file could hold.
std::size_t capped_count(std::uint64_t announced, std::size_t bytes, std::size_t min_bytes_each);

/// Appends a polygon (at least 3 valid corners) to the soup, fan-triangulated around its first
/// corner, and counts it in report.faces_in_file and report.polygons_triangulated. A `patch` other
/// than 0 is given to its triangles (soup.patches is kept empty until a face has one, then 0 marks
/// the faces without; parse_soup settles those, see io.h).
void add_polygon(TriangleSoup& soup, const std::vector<std::uint32_t>& corners, ReadReport& report, int patch = 0);

/// The tags of a file's named groups: a new tag, 1, 2, ..., the first time a name is met, its name
/// stored in soup.patch_names.
class GroupTags {
 public:
  int tag(TriangleSoup& soup, const std::string& name);

 private:
  std::map<std::string, int> tag_of_;
};

}  // namespace meshprep::detail
