#include "vtu_writer.h"

#include "byte_order.h"
#include "exporters.h"
#include "text_buffer.h"

#include <tbb/parallel_for.h>
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
  if constexpr (host_is_little_endian) {
    array.bytes.assign(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
    return array;
  }
  array.bytes.reserve(values.size() * sizeof(T));
  for (const T value : values) append_little_endian(array.bytes, value);
  return array;
}

// ASCII values, `per_line` to a line: formatting is most of an ASCII file's cost, so batches of
// lines are formatted in parallel, each chunk into its own text, and written in order.
template <class T>
void write_ascii_values(std::ostream& out, const VtuArray& array) {
  constexpr std::size_t kLinesPerChunk = 4096, kChunksPerBatch = 64;
  const std::size_t count = array.bytes.size() / sizeof(T);
  const std::size_t lines = (count + array.per_line - 1) / array.per_line;
  std::vector<std::string> chunks(kChunksPerBatch);
  for (std::size_t batch_line = 0; batch_line < lines; batch_line += kLinesPerChunk * kChunksPerBatch) {
    const std::size_t num_chunks = std::min(kChunksPerBatch, (lines - batch_line + kLinesPerChunk - 1) / kLinesPerChunk);
    tbb::parallel_for(std::size_t{0}, num_chunks, [&](std::size_t c) {
      std::string& text = chunks[c];
      text.clear();
      const std::size_t first = (batch_line + c * kLinesPerChunk) * array.per_line;
      const std::size_t last = std::min(count, first + kLinesPerChunk * array.per_line);
      for (std::size_t i = first; i < last; ++i) {
        text += i % array.per_line == 0 ? "          " : " ";
        append_number(text, load_value<T>(array.bytes.data() + i * sizeof(T), /*little_endian=*/true));
        if ((i + 1) % array.per_line == 0 || i + 1 == count) text += '\n';
      }
    });
    for (std::size_t c = 0; c < num_chunks; ++c) out.write(chunks[c].data(), static_cast<std::streamsize>(chunks[c].size()));
  }
}

void write_ascii_values(std::ostream& out, const VtuArray& array) {
  const std::string type = array.type;
  if (type == "Float64") write_ascii_values<double>(out, array);
  if (type == "Float32") write_ascii_values<float>(out, array);
  if (type == "Int64") write_ascii_values<std::int64_t>(out, array);
  if (type == "Int32") write_ascii_values<std::int32_t>(out, array);
  if (type == "UInt8") write_ascii_values<std::uint8_t>(out, array);
}

// zlib at its fastest level with run-length matching only (Z_RLE): on the femur's tets the data
// compress 2.2x faster than with the level's full matching, to a file 9 % larger
// (bench/bench_writers.sh); the streams are ordinary zlib ones, which every reader inflates.
constexpr int kCompressionLevel = Z_BEST_SPEED;
constexpr int kCompressionStrategy = Z_RLE;

// One block as a zlib stream (compress2's, with kCompressionStrategy); zlib's status.
int compress_block(const char* data, std::size_t size, std::string& compressed) {
  z_stream stream{};
  int status = deflateInit2(&stream, kCompressionLevel, Z_DEFLATED, MAX_WBITS, /*memLevel=*/8, kCompressionStrategy);
  if (status != Z_OK) return status;
  compressed.resize(deflateBound(&stream, static_cast<uLong>(size)));
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data));
  stream.avail_in = static_cast<uInt>(size);
  stream.next_out = reinterpret_cast<Bytef*>(compressed.data());
  stream.avail_out = static_cast<uInt>(compressed.size());
  status = deflate(&stream, Z_FINISH);
  compressed.resize(stream.total_out);
  deflateEnd(&stream);
  return status == Z_STREAM_END ? Z_OK : (status == Z_OK ? Z_BUF_ERROR : status);
}

// `bytes` as VTK's compressed block list: the UInt64 header, then the zlib streams, as pieces to
// write one after the other (not joined: on a second-order mesh copying them cost as much as the
// compression). The blocks are independent, so they are compressed in parallel.
std::vector<std::string> compressed_blocks(const std::string& bytes) {
  const std::size_t num_blocks = (bytes.size() + kBlockSize - 1) / kBlockSize;
  std::vector<std::string> pieces(num_blocks + 1);  // the header, then the blocks
  std::vector<int> status(num_blocks, Z_OK);
  tbb::parallel_for(std::size_t{0}, num_blocks, [&](std::size_t b) {
    const std::size_t size = std::min(kBlockSize, bytes.size() - b * kBlockSize);
    status[b] = compress_block(bytes.data() + b * kBlockSize, size, pieces[b + 1]);
  });
  std::string& header = pieces[0];
  append_little_endian(header, std::uint64_t{num_blocks});
  append_little_endian(header, std::uint64_t{kBlockSize});
  append_little_endian(header, std::uint64_t{bytes.size() % kBlockSize});
  for (std::size_t b = 0; b < num_blocks; ++b) {
    if (status[b] != Z_OK) throw std::runtime_error(std::string("zlib cannot compress a .vtu block: ") + zError(status[b]));
    append_little_endian(header, std::uint64_t{pieces[b + 1].size()});
  }
  return pieces;
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
      out_ << " format=\"appended\" offset=\"" << appended_size_ << "\"/>\n";
      for (std::string& piece : compressed_blocks(array.bytes)) {
        appended_size_ += piece.size();
        appended_.push_back(std::move(piece));
      }
      return;
    }
    out_ << " format=\"ascii\">\n";
    write_ascii_values(out_, array);
    out_ << "        </DataArray>\n";
  }

  /// The appended data: every binary array's compressed blocks, in the order written.
  const std::vector<std::string>& appended() const { return appended_; }

 private:
  std::ostream& out_;
  bool binary_;
  std::vector<std::string> appended_;
  std::size_t appended_size_ = 0;
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
VtuArray vtu_array(std::string name, const std::vector<float>& values, std::size_t components, std::size_t per_line) {
  return make_array(std::move(name), "Float32", values, components, per_line);
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
    for (const std::string& data : arrays.appended()) out.write(data.data(), static_cast<std::streamsize>(data.size()));
    out << "\n  </AppendedData>\n";
  }
  out << "</VTKFile>\n";
}

}  // namespace meshprep::detail
