// Soup writers: OFF, OBJ, PLY (ASCII or binary little endian, double coordinates and per-vertex
// scalars) and STL (ASCII or binary float32 with facet normals). Text numbers are written with
// std::to_chars, the shortest text that reads back to the identical double. Patches: OBJ `g`
// groups, a PLY face property `patch` with `comment patch <tag> <name>` lines, one ASCII STL
// solid per patch (in tag order); OFF and binary STL have no place for them.
#include "meshprep/core/io.h"

#include "meshprep/core/atomic_file.h"
#include "byte_order.h"
#include "readers.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <ostream>
#include <sstream>

namespace meshprep {
namespace {

// Collects output in memory and hands it to the stream in large blocks.
class OutputBuffer {
 public:
  explicit OutputBuffer(std::ostream& out) : out_(out) { buffer_.reserve(flush_size + 4096); }

  OutputBuffer& operator<<(std::string_view text) {
    buffer_ += text;
    return maybe_flush();
  }
  OutputBuffer& operator<<(double value) { return append_chars(value); }
  OutputBuffer& operator<<(std::size_t value) { return append_chars(value); }
  OutputBuffer& operator<<(std::uint32_t value) { return append_chars(value); }

  template <class T>
  void binary(T value) {
    detail::append_little_endian(buffer_, value);
    maybe_flush();
  }

  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }

 private:
  static constexpr std::size_t flush_size = std::size_t{1} << 20;

  template <class T>
  OutputBuffer& append_chars(T value) {
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value);
    buffer_.append(text, result.ptr);
    return maybe_flush();
  }
  OutputBuffer& maybe_flush() {
    if (buffer_.size() >= flush_size) flush();
    return *this;
  }

  std::ostream& out_;
  std::string buffer_;
};

// The tags of soup.patches, ascending.
std::vector<int> distinct_patches(const TriangleSoup& soup) {
  std::vector<int> tags = soup.patches;
  std::sort(tags.begin(), tags.end());
  tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
  return tags;
}

void write_point(OutputBuffer& out, const Vec3& p) { out << p.x() << " " << p.y() << " " << p.z(); }

Vec3 unit_normal(const TriangleSoup& soup, const Triangle& t) {
  const Vec3 normal = (soup.points[t[1]] - soup.points[t[0]]).cross(soup.points[t[2]] - soup.points[t[0]]);
  const double length = normal.norm();
  return length > 0.0 ? Vec3(normal / length) : Vec3::Zero();
}

void write_off(const TriangleSoup& soup, OutputBuffer& out) {
  out << "OFF\n" << soup.points.size() << " " << soup.triangles.size() << " 0\n";
  for (const Vec3& p : soup.points) {
    write_point(out, p);
    out << "\n";
  }
  for (const Triangle& t : soup.triangles) out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
}

void write_obj(const TriangleSoup& soup, OutputBuffer& out) {
  for (const Vec3& p : soup.points) {
    out << "v ";
    write_point(out, p);
    out << "\n";
  }
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    if (!soup.patches.empty() && (f == 0 || soup.patches[f] != soup.patches[f - 1]))
      out << "g " << tag_name(soup.patch_names, soup.patches[f], "patch") << "\n";
    const Triangle& t = soup.triangles[f];
    out << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
  }
}

void write_ply(const TriangleSoup& soup, const std::vector<VertexScalar>& scalars, OutputBuffer& out, bool binary) {
  const bool patches = !soup.patches.empty();
  out << "ply\nformat " << (binary ? "binary_little_endian" : "ascii") << " 1.0\ncomment written by meshprep\n";
  if (patches)
    for (const int tag : distinct_patches(soup))
      out << "comment patch " << static_cast<std::size_t>(tag) << " " << tag_name(soup.patch_names, tag, "patch") << "\n";
  out << "element vertex " << soup.points.size() << "\nproperty double x\nproperty double y\nproperty double z\n";
  for (const VertexScalar& scalar : scalars) out << "property double " << scalar.name << "\n";
  out << "element face " << soup.triangles.size() << "\nproperty list uchar uint vertex_indices\n";
  if (patches) out << "property int patch\n";
  out << "end_header\n";
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    const Vec3& p = soup.points[i];
    if (binary) {
      for (int k = 0; k < 3; ++k) out.binary(p[k]);
      for (const VertexScalar& scalar : scalars) out.binary(scalar.values[i]);
    } else {
      write_point(out, p);
      for (const VertexScalar& scalar : scalars) out << " " << scalar.values[i];
      out << "\n";
    }
  }
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const Triangle& t = soup.triangles[f];
    if (binary) {
      out.binary(std::uint8_t{3});
      for (const std::uint32_t index : t) out.binary(index);
      if (patches) out.binary(static_cast<std::int32_t>(soup.patches[f]));
    } else {
      out << "3 " << t[0] << " " << t[1] << " " << t[2];
      if (patches) out << " " << static_cast<std::size_t>(soup.patches[f]);
      out << "\n";
    }
  }
}

void write_stl_facet(const TriangleSoup& soup, const Triangle& t, OutputBuffer& out) {
  out << "  facet normal ";
  write_point(out, unit_normal(soup, t));
  out << "\n    outer loop\n";
  for (const std::uint32_t index : t) {
    out << "      vertex ";
    write_point(out, soup.points[index]);
    out << "\n";
  }
  out << "    endloop\n  endfacet\n";
}

void write_stl_ascii(const TriangleSoup& soup, OutputBuffer& out) {
  if (soup.patches.empty()) {
    out << "solid meshprep\n";
    for (const Triangle& t : soup.triangles) write_stl_facet(soup, t, out);
    out << "endsolid meshprep\n";
    return;
  }
  for (const int tag : distinct_patches(soup)) {
    const std::string name = tag_name(soup.patch_names, tag, "patch");
    out << "solid " << name << "\n";
    for (std::size_t f = 0; f < soup.triangles.size(); ++f)
      if (soup.patches[f] == tag) write_stl_facet(soup, soup.triangles[f], out);
    out << "endsolid " << name << "\n";
  }
}

void write_stl_binary(const TriangleSoup& soup, OutputBuffer& out) {
  // The header must not start with "solid", or some readers would take the file for ASCII.
  std::string header = "binary STL written by meshprep";
  header.resize(80, ' ');
  out << header;
  out.binary(static_cast<std::uint32_t>(soup.triangles.size()));
  const auto write_floats = [&out](const Vec3& v) {
    for (int k = 0; k < 3; ++k) out.binary(static_cast<float>(v[k]));
  };
  for (const Triangle& t : soup.triangles) {
    write_floats(unit_normal(soup, t));
    for (const std::uint32_t index : t) write_floats(soup.points[index]);
    out.binary(std::uint16_t{0});
  }
}

// The soup invariant, and what the formats can hold; checked before anything is written.
void check_writable(const TriangleSoup& soup, const std::string& path) {
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    if (!detail::is_finite(soup.points[i])) {
      detail::fail(path, "cannot write point " + std::to_string(i) + ": non-finite coordinate (" +
                             detail::non_finite_text(soup.points[i]) + ")");
    }
  }
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    for (const std::uint32_t index : soup.triangles[f]) {
      if (index >= soup.points.size()) {
        detail::fail(path, "cannot write triangle " + std::to_string(f) + ": vertex index " + std::to_string(index) +
                               " out of range (" + std::to_string(soup.points.size()) + " points)");
      }
    }
  }
  if (soup.triangles.size() > std::numeric_limits<std::uint32_t>::max()) {
    detail::fail(path, "too many triangles for the file format");
  }
  if (!soup.patches.empty() && soup.patches.size() != soup.triangles.size())
    detail::fail(path, "cannot write " + std::to_string(soup.patches.size()) + " patches for " +
                           std::to_string(soup.triangles.size()) + " triangles");
  for (const int tag : soup.patches)
    if (tag < 1) detail::fail(path, "cannot write patch " + std::to_string(tag) + " (a patch is >= 1)");
  for (const auto& [tag, name] : soup.patch_names)
    if (!is_valid_name(name))
      detail::fail(path, "cannot write the patch name '" + name + "': " + kNameRule);
}

// Binary STL holds float32 coordinates: far from the origin (or for tiny features) they cannot
// tell a triangle's corners apart, and the file would hold a different, degenerate mesh.
void check_float32_corners(const TriangleSoup& soup, const std::string& path) {
  const auto as_float = [](const Vec3& p) { return p.cast<float>().eval(); };
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const Triangle& t = soup.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const Vec3& a = soup.points[t[k]];
      const Vec3& b = soup.points[t[(k + 1) % 3]];
      if (a == b || as_float(a) != as_float(b)) continue;
      std::ostringstream problem;
      problem << "binary STL stores float32 coordinates, which cannot tell the corners of triangle " << f
              << " apart (" << (a - b).norm() << " from each other, " << a.cwiseAbs().maxCoeff()
              << " from the origin); write PLY, OFF, OBJ or ASCII STL instead";
      detail::fail(path, problem.str());
    }
  }
}

// A PLY property name is one word; x, y and z are taken by the coordinates.
bool is_valid_scalar_name(const std::string& name) {
  if (name.empty() || name == "x" || name == "y" || name == "z") return false;
  for (const char c : name) {
    if (c <= ' ' || c > '~') return false;  // whitespace, control characters and non-ASCII bytes
  }
  return true;
}

// One finite value per point under a valid, distinct name; checked before anything is written.
void check_vertex_scalars(const TriangleSoup& soup, const std::vector<VertexScalar>& scalars, const std::string& path) {
  for (std::size_t s = 0; s < scalars.size(); ++s) {
    const VertexScalar& scalar = scalars[s];
    const std::string name = "'" + scalar.name + "'";
    if (!is_valid_scalar_name(scalar.name)) {
      detail::fail(path, "cannot write vertex scalar " + name + ": a name is one printable word other than x, y, z");
    }
    for (std::size_t earlier = 0; earlier < s; ++earlier) {
      if (scalars[earlier].name == scalar.name) detail::fail(path, "cannot write vertex scalar " + name + " twice");
    }
    if (scalar.values.size() != soup.points.size()) {
      detail::fail(path, "cannot write vertex scalar " + name + ": " + std::to_string(scalar.values.size()) +
                             " values for " + std::to_string(soup.points.size()) + " points");
    }
    for (std::size_t i = 0; i < scalar.values.size(); ++i) {
      if (!std::isfinite(scalar.values[i])) {
        detail::fail(path, "cannot write vertex scalar " + name + ": value " + std::to_string(i) + " is not finite");
      }
    }
  }
}

}  // namespace

void write_soup(const TriangleSoup& soup, const std::string& path, const WriteOptions& options) {
  const std::string extension = extension_of(path);
  if (extension != "off" && extension != "obj" && extension != "ply" && extension != "stl") {
    detail::fail(path, detail::unknown_extension_problem(extension));
  }
  check_writable(soup, path);
  check_vertex_scalars(soup, options.vertex_scalars, path);
  const bool binary = options.binary && (extension == "ply" || extension == "stl");
  if (binary && extension == "stl") check_float32_corners(soup, path);
  write_file_atomically(
      path,
      [&](std::ostream& stream) {
        OutputBuffer out(stream);
        if (extension == "off") {
          write_off(soup, out);
        } else if (extension == "obj") {
          write_obj(soup, out);
        } else if (extension == "ply") {
          write_ply(soup, options.vertex_scalars, out, binary);
        } else if (binary) {
          write_stl_binary(soup, out);
        } else {
          write_stl_ascii(soup, out);
        }
        out.flush();
      },
      binary);
}

}  // namespace meshprep
