// PLY reader: ASCII, binary little and big endian. The header's elements and properties drive
// the parse: every property of every element is read (or skipped) in order, so unknown
// properties and elements cost nothing but cannot shift the data. A scalar integer face property
// `patch`, `label` or `tag` (the first of these the header declares) gives each face its patch;
// `comment patch <value> <name>` lines name them (what write_soup writes).
#include "byte_order.h"
#include "ply_header.h"
#include "readers.h"
#include "text_scanner.h"

#include <algorithm>
#include <limits>
#include <map>
#include <optional>

namespace meshprep::detail {
namespace {

// Tags stay far from int's end, so that a fresh tag after the largest still fits.
constexpr std::int64_t kLargestTag = std::int64_t{1} << 30;

// Thrown by a source that runs out of data; read_ply turns it into a "truncated" message.
struct OutOfData {};

// Values of the data section of an ASCII file.
class AsciiSource {
 public:
  AsciiSource(const std::string& path, std::string_view data, std::size_t first_line)
      : path_(path), in_(data, '\0', first_line) {}

  double real(PlyType type) {
    const std::string_view token = next();
    if (is_integral(type)) return static_cast<double>(integer_of(token, type));
    double value = 0.0;
    if (!parse_double(token, value)) fail(path_, where() + quoted(token) + " is not a number");
    return value;
  }
  std::int64_t integer(PlyType type) { return integer_of(next(), type); }
  void skip(PlyType type) { real(type); }
  bool at_end() { return !in_.seek_token(); }
  std::string where() const { return at_line(in_.line()); }

 private:
  std::string_view next() {
    if (!in_.seek_token()) throw OutOfData{};
    return in_.token();
  }
  std::int64_t integer_of(std::string_view token, PlyType type) {
    std::int64_t value = 0;
    if (!parse_int(token, value) || !fits(type, value)) {
      fail(path_, where() + quoted(token) + " is not a valid integer of the declared type");
    }
    return value;
  }

  const std::string& path_;
  TextScanner in_;
};

// Values of the data section of a binary file.
class BinarySource {
 public:
  BinarySource(std::string_view data, bool little_endian) : data_(data), little_endian_(little_endian) {}

  double real(PlyType type) {
    switch (type) {
      case PlyType::Float32:
        return load<float>();
      case PlyType::Float64:
        return load<double>();
      default:
        return static_cast<double>(integer(type));
    }
  }
  std::int64_t integer(PlyType type) {
    switch (type) {
      case PlyType::Int8:
        return load<std::int8_t>();
      case PlyType::UInt8:
        return load<std::uint8_t>();
      case PlyType::Int16:
        return load<std::int16_t>();
      case PlyType::UInt16:
        return load<std::uint16_t>();
      case PlyType::Int32:
        return load<std::int32_t>();
      case PlyType::UInt32:
        return load<std::uint32_t>();
      default:
        return 0;  // the header allows only integer types where integers are read
    }
  }
  void skip(PlyType type) { take(size_of(type)); }
  bool at_end() const { return offset_ == data_.size(); }
  std::string where() const { return {}; }

 private:
  const char* take(std::size_t n) {
    if (data_.size() - offset_ < n) throw OutOfData{};
    const char* bytes = data_.data() + offset_;
    offset_ += n;
    return bytes;
  }
  template <class T>
  T load() {
    return load_value<T>(take(sizeof(T)), little_endian_);
  }

  std::string_view data_;
  std::size_t offset_ = 0;
  bool little_endian_;
};

// "vertices", "faces" or "'edge' elements", for messages.
std::string plural(const std::string& element) {
  if (element == "vertex") return "vertices";
  if (element == "face") return "faces";
  return quoted(element) + " elements";
}

const PlyElement* find_element(const std::string& path, const PlyHeader& header, const std::string& name) {
  const PlyElement* found = nullptr;
  for (const PlyElement& element : header.elements) {
    if (element.name != name) continue;
    if (found) fail(path, "the header declares the element " + quoted(name) + " twice");
    found = &element;
  }
  return found;
}

// Index of the property `name` of `element`.
std::optional<std::size_t> find_property(const PlyElement& element, std::string_view name) {
  for (std::size_t i = 0; i < element.properties.size(); ++i) {
    if (element.properties[i].name == name) return i;
  }
  return std::nullopt;
}

// Reads the data section through `Source` (AsciiSource or BinarySource).
class PlyDataReader {
 public:
  PlyDataReader(const std::string& path, const PlyHeader& header, ReadReport& report)
      : path_(path), header_(header), report_(report) {}

  template <class Source>
  TriangleSoup read(Source& source, std::size_t data_bytes) {
    locate_vertex_and_face_properties();
    for (const PlyElement& element : header_.elements) {
      if (&element == vertex_) soup_.points.reserve(capped_count(element.count, data_bytes, min_bytes(element)));
      if (&element == face_) soup_.triangles.reserve(capped_count(element.count, data_bytes, min_bytes(element)));
      if (element.properties.empty()) continue;  // instances without properties take no data
      std::uint64_t i = 0;
      try {
        for (; i < element.count; ++i) read_instance(source, element, i);
      } catch (const OutOfData&) {
        fail(path_, "truncated: header announces " + std::to_string(element.count) + " " + plural(element.name) +
                        ", data has " + std::to_string(i));
      }
    }
    if (!source.at_end()) fail(path_, source.where() + "unexpected data after the last element");
    name_patches();
    return std::move(soup_);
  }

 private:
  void locate_vertex_and_face_properties() {
    vertex_ = find_element(path_, header_, "vertex");
    face_ = find_element(path_, header_, "face");
    if (!vertex_) fail(path_, "the header has no 'vertex' element");
    if (vertex_->count > std::numeric_limits<std::uint32_t>::max()) {
      fail(path_, "too many vertices (" + std::to_string(vertex_->count) + ")");
    }
    const char* name[] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k) {
      const std::optional<std::size_t> index = find_property(*vertex_, name[k]);
      if (!index || vertex_->properties[*index].is_list) {
        fail(path_, std::string("the 'vertex' element has no scalar property '") + name[k] + "'");
      }
      xyz_[k] = *index;
    }
    if (!face_) return;
    std::optional<std::size_t> index = find_property(*face_, "vertex_indices");
    if (!index) index = find_property(*face_, "vertex_index");
    if (!index || !face_->properties[*index].is_list) {
      fail(path_, "the 'face' element has no list property 'vertex_indices'");
    }
    if (!is_integral(face_->properties[*index].type)) {
      fail(path_, "the 'face' vertex indices are not of an integer type");
    }
    corners_ = *index;
    for (const char* label : {"patch", "label", "tag"}) {
      const std::optional<std::size_t> found = find_property(*face_, label);
      if (!found || face_->properties[*found].is_list || !is_integral(face_->properties[*found].type)) continue;
      patch_property_ = *found;
      report_.patches_from = std::string("ply face property '") + label + "'";
      break;
    }
  }

  // The file's label values made tags >= 1 (shifted up when the file counts from 0 or below),
  // named by the header's `comment patch <value> <name>` lines, else "patch_<value>".
  void name_patches() {
    if (!patch_property_ || labels_.empty()) return;
    const auto [low, high] = std::minmax_element(labels_.begin(), labels_.end());
    const std::int64_t shift = *low < 1 ? 1 - *low : 0;
    if (*high + shift > kLargestTag)
      fail(path_, "face " + report_.patches_from.substr(4) + " spans " + std::to_string(*low) + " to " +
                      std::to_string(*high) + ", more tags than a mesh can hold");
    std::map<std::int64_t, std::string> named;
    for (const std::string& comment : header_.comments) {
      TextScanner words(comment);
      std::int64_t value = 0;
      if (words.token() != "patch" || !parse_int(words.token(), value)) continue;
      const std::string_view name = words.rest_of_line();
      if (!name.empty()) named[value] = std::string(name);
    }
    soup_.patches.resize(soup_.triangles.size());
    std::size_t triangle = 0;
    for (std::size_t face = 0; face < labels_.size(); ++face) {
      const int tag = static_cast<int>(labels_[face] + shift);
      for (std::size_t t = 0; t < triangles_of_face_[face]; ++t) soup_.patches[triangle++] = tag;
      if (!soup_.patch_names.count(tag)) {
        const auto name = named.find(labels_[face]);
        soup_.patch_names[tag] = name != named.end() ? name->second : "patch_" + std::to_string(labels_[face]);
      }
    }
  }

  // The fewest bytes an instance of `element` can take (binary size, or a digit and a separator per value).
  std::size_t min_bytes(const PlyElement& element) const {
    const bool ascii = header_.format == PlyFormat::Ascii;
    std::size_t bytes = 0;
    for (const PlyProperty& property : element.properties) {
      bytes += ascii ? 2 : size_of(property.is_list ? property.count_type : property.type);
    }
    return bytes;
  }

  // 0, 1 or 2 if property k of the vertex element is x, y or z; else -1.
  int axis_of(std::size_t k) const {
    for (int axis = 0; axis < 3; ++axis) {
      if (xyz_[axis] == k) return axis;
    }
    return -1;
  }

  template <class Source>
  void read_instance(Source& source, const PlyElement& element, std::uint64_t i) {
    Vec3 p;
    for (std::size_t k = 0; k < element.properties.size(); ++k) {
      const PlyProperty& property = element.properties[k];
      if (!property.is_list) {
        const int axis = &element == vertex_ ? axis_of(k) : -1;
        if (axis >= 0) {
          p[axis] = source.real(property.type);
        } else if (&element == face_ && patch_property_ == k) {
          labels_.push_back(source.integer(property.type));
        } else {
          source.skip(property.type);
        }
        continue;
      }
      const std::int64_t count = source.integer(property.count_type);
      if (count < 0) {
        fail(path_, source.where() + element.name + " " + std::to_string(i) + ": negative list length " +
                        std::to_string(count));
      }
      if (&element == face_ && k == corners_) {
        read_face(source, property, count, i);
      } else {
        for (std::int64_t j = 0; j < count; ++j) source.skip(property.type);
      }
    }
    if (&element != vertex_) return;
    if (!is_finite(p)) {
      fail(path_, source.where() + "vertex " + std::to_string(i) + " has a non-finite coordinate (" +
                      non_finite_text(p) + ")");
    }
    soup_.points.push_back(p);
  }

  template <class Source>
  void read_face(Source& source, const PlyProperty& property, std::int64_t count, std::uint64_t i) {
    const auto problem = [&](const std::string& text) {
      fail(path_, source.where() + "face " + std::to_string(i) + text);
    };
    // Usually a header that announces more vertices than there are: the faces' data was read as vertices.
    if (count < 3)
      problem(" has " + std::to_string(count) + " corners (at least 3 needed; is the header's vertex count, " +
              std::to_string(vertex_->count) + ", right?)");
    corners_of_face_.clear();
    for (std::int64_t j = 0; j < count; ++j) {
      const std::int64_t index = source.integer(property.type);
      if (index < 0) problem(" has a negative vertex index (" + std::to_string(index) + ")");
      if (static_cast<std::uint64_t>(index) >= vertex_->count) {
        problem(": vertex index " + std::to_string(index) + " out of range (" + std::to_string(vertex_->count) +
                " vertices)");
      }
      corners_of_face_.push_back(static_cast<std::uint32_t>(index));
    }
    add_polygon(soup_, corners_of_face_, report_);
    if (patch_property_) triangles_of_face_.push_back(static_cast<std::uint32_t>(corners_of_face_.size() - 2));
  }

  const std::string& path_;
  const PlyHeader& header_;
  ReadReport& report_;
  const PlyElement* vertex_ = nullptr;
  const PlyElement* face_ = nullptr;
  std::size_t xyz_[3] = {0, 0, 0};
  std::size_t corners_ = 0;
  std::vector<std::uint32_t> corners_of_face_;
  std::optional<std::size_t> patch_property_;  // of the face element
  std::vector<std::int64_t> labels_;             // its value per face
  std::vector<std::uint32_t> triangles_of_face_;  // per face, the triangles it became
  TriangleSoup soup_;
};

}  // namespace

TriangleSoup read_ply(const std::string& path, std::string_view data, ReadReport& report) {
  const PlyHeader header = parse_ply_header(path, data);
  const std::string_view body = data.substr(header.data_offset);
  PlyDataReader reader(path, header, report);
  if (header.format == PlyFormat::Ascii) {
    report.format = "ply-ascii";
    AsciiSource source(path, body, header.data_line);
    return reader.read(source, body.size());
  }
  report.format = "ply-binary";
  BinarySource source(body, header.format == PlyFormat::BinaryLittleEndian);
  return reader.read(source, body.size());
}

}  // namespace meshprep::detail
