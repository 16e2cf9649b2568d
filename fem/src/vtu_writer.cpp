#include "vtu_writer.h"

#include "byte_order.h"
#include "exporters.h"

#include <zlib.h>

#include <algorithm>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace meshprep::detail {
namespace {

// VTK's own block size (vtkDataCompressor): 32 KiB of data per compressed block.
constexpr std::size_t kBlockSize = 32768;

template <class T>
VtuArray make_array(std::string name, const char* type, const std::vector<T>& values, std::size_t components,
                    std::size_t per_line) {
  VtuArray array{std::move(name), type, components, per_line, {}};
  array.bytes.reserve(values.size() * sizeof(T));
  for (const T value : values) append_little_endian(array.bytes, value);
  return array;
}

template <class T>
void write_ascii_values(std::ostream& out, const VtuArray& array) {
  const std::size_t count = array.bytes.size() / sizeof(T);
  for (std::size_t i = 0; i < count; ++i) {
    out << (i % array.per_line == 0 ? "          " : " ");
    const T value = load_value<T>(array.bytes.data() + i * sizeof(T), /*little_endian=*/true);
    if constexpr (std::is_floating_point_v<T>)
      write_real(out, value);
    else
      out << +value;  // + prints a UInt8 as a number
    if ((i + 1) % array.per_line == 0 || i + 1 == count) out << '\n';
  }
}

void write_ascii_values(std::ostream& out, const VtuArray& array) {
  const std::string type = array.type;
  if (type == "Float64") write_ascii_values<double>(out, array);
  if (type == "Int64") write_ascii_values<std::int64_t>(out, array);
  if (type == "Int32") write_ascii_values<std::int32_t>(out, array);
  if (type == "UInt8") write_ascii_values<std::uint8_t>(out, array);
}

// zlib's fastest level: on the femur's tets the .vtu is written 1.8x faster than at its default
// level (6), for a file 1.5 % larger (bench/bench_writers.sh).
constexpr int kCompressionLevel = Z_BEST_SPEED;

// `bytes` as VTK's compressed block list: the UInt64 header, then the zlib streams.
std::string compressed_blocks(const std::string& bytes) {
  const std::size_t num_blocks = (bytes.size() + kBlockSize - 1) / kBlockSize;
  std::string header, data;
  append_little_endian(header, std::uint64_t{num_blocks});
  append_little_endian(header, std::uint64_t{kBlockSize});
  append_little_endian(header, std::uint64_t{bytes.size() % kBlockSize});
  std::string compressed(compressBound(kBlockSize), '\0');
  for (std::size_t b = 0; b < num_blocks; ++b) {
    const std::size_t size = std::min(kBlockSize, bytes.size() - b * kBlockSize);
    uLongf compressed_size = static_cast<uLongf>(compressed.size());
    const int status = compress2(reinterpret_cast<Bytef*>(compressed.data()), &compressed_size,
                                 reinterpret_cast<const Bytef*>(bytes.data() + b * kBlockSize), static_cast<uLong>(size),
                                 kCompressionLevel);
    if (status != Z_OK) throw std::runtime_error(std::string("zlib cannot compress a .vtu block: ") + zError(status));
    append_little_endian(header, std::uint64_t{compressed_size});
    data.append(compressed.data(), compressed_size);
  }
  return header + data;
}

// Writes the arrays' <DataArray> elements; binary ones get their offset in `appended`, to which
// their compressed data is added.
class ArrayWriter {
 public:
  ArrayWriter(std::ostream& out, bool binary) : out_(out), binary_(binary) {}

  void write(const VtuArray& array) {
    out_ << "        <DataArray type=\"" << array.type << '"';
    if (!array.name.empty()) out_ << " Name=\"" << array.name << '"';
    if (array.components > 1) out_ << " NumberOfComponents=\"" << array.components << '"';
    if (binary_) {
      out_ << " format=\"appended\" offset=\"" << appended_.size() << "\"/>\n";
      appended_ += compressed_blocks(array.bytes);
      return;
    }
    out_ << " format=\"ascii\">\n";
    write_ascii_values(out_, array);
    out_ << "        </DataArray>\n";
  }

  const std::string& appended() const { return appended_; }

 private:
  std::ostream& out_;
  bool binary_;
  std::string appended_;
};

void write_tag_names(std::ostream& out, const std::vector<VtuTagName>& names) {
  if (names.empty()) return;
  out << "    <FieldData>\n";
  for (const VtuTagName& n : names)
    out << "      <DataArray type=\"Int32\" Name=\"" << n.name
        << "\" NumberOfTuples=\"1\" NumberOfComponents=\"2\" format=\"ascii\">" << n.tag << ' ' << n.dimension
        << "</DataArray>\n";
  out << "    </FieldData>\n";
}

}  // namespace

VtuArray vtu_array(std::string name, const std::vector<double>& values, std::size_t components, std::size_t per_line) {
  return make_array(std::move(name), "Float64", values, components, per_line);
}
VtuArray vtu_array(std::string name, const std::vector<std::int64_t>& values, std::size_t components,
                   std::size_t per_line) {
  return make_array(std::move(name), "Int64", values, components, per_line);
}
VtuArray vtu_array(std::string name, const std::vector<std::int32_t>& values, std::size_t components,
                   std::size_t per_line) {
  return make_array(std::move(name), "Int32", values, components, per_line);
}
VtuArray vtu_array(std::string name, const std::vector<std::uint8_t>& values, std::size_t components,
                   std::size_t per_line) {
  return make_array(std::move(name), "UInt8", values, components, per_line);
}

void write_vtu_piece(std::ostream& out, const VtuPiece& piece, bool binary) {
  out << "<?xml version=\"1.0\"?>\n";
  if (binary)
    out << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\" "
           "compressor=\"vtkZLibDataCompressor\">\n";
  else
    out << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n";
  out << "  <UnstructuredGrid>\n";
  write_tag_names(out, piece.tag_names);
  out << "    <Piece NumberOfPoints=\"" << piece.num_points << "\" NumberOfCells=\"" << piece.num_cells << "\">\n";
  ArrayWriter arrays(out, binary);
  if (!piece.point_data.empty()) {
    out << "      <PointData>\n";
    for (const VtuArray& array : piece.point_data) arrays.write(array);
    out << "      </PointData>\n";
  }
  out << "      <Points>\n";
  arrays.write(piece.points);
  out << "      </Points>\n"
      << "      <Cells>\n";
  arrays.write(piece.connectivity);
  arrays.write(piece.offsets);
  arrays.write(piece.types);
  out << "      </Cells>\n";
  if (!piece.cell_data.empty()) {
    out << "      <CellData" << (piece.cell_scalars.empty() ? "" : " Scalars=\"" + piece.cell_scalars + '"') << ">\n";
    for (const VtuArray& array : piece.cell_data) arrays.write(array);
    out << "      </CellData>\n";
  }
  out << "    </Piece>\n"
      << "  </UnstructuredGrid>\n";
  if (binary) {
    // meshio takes the data to run from the '_' to the last line break before </AppendedData>.
    out << "  <AppendedData encoding=\"raw\">\n   _";
    out.write(arrays.appended().data(), static_cast<std::streamsize>(arrays.appended().size()));
    out << "\n  </AppendedData>\n";
  }
  out << "</VTKFile>\n";
}

}  // namespace meshprep::detail
