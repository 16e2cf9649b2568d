// The only translation unit that runs TetGen. TetGen (Hang Si, "TetGen, a Delaunay-based quality
// tetrahedral mesh generator", ACM TOMS 41(2), 2015) is called through its library interface with
// TETLIBRARY defined, so its errors are thrown as an int code; the call runs in a forked child
// (isolated_call.h) so that anything worse than a throw is reported too.
#include "meshprep/fem/tetrahedralize.h"

#include "meshprep/core/origin_shift.h"
#include "meshprep/core/union_find.h"
#include "meshprep/quality/triangle_metrics.h"

#include "isolated_call.h"

#include <tetgen.h>

#include <cmath>
#include <cstring>
#include <map>
#include <sstream>

namespace meshprep {
namespace {

// Messages for TetGen's error codes (tetgen.h, terminatetetgen), with what to do about each.
std::string explain_tetgen_code(int code) {
  switch (code) {
    case 1: return "TetGen ran out of memory; coarsen the surface or raise --max-volume";
    case 2: return "TetGen hit an internal error; try --keep-surface or a slightly perturbed surface";
    case 3: return "TetGen found self-intersecting facets; run `meshprep quality` to list the intersecting faces";
    case 4: return "TetGen found a feature too small to mesh (very close or nearly collinear points); simplify the "
                   "surface or remove its tiny faces";
    case 5: return "TetGen found two facets too close to each other (nearly overlapping); try --keep-surface or "
                   "repair the surface there";
    case 10: return "TetGen rejected the input (invalid facets or switches)";
    default: return "TetGen failed with code " + std::to_string(code);
  }
}

// A tiny binary stream for passing the result from the child to the parent.
template <class T>
void put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}
template <class T>
void put_vector(std::string& out, const std::vector<T>& v) {
  put(out, static_cast<std::uint64_t>(v.size()));
  out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}
struct Reader {
  const std::string& in;
  std::size_t at = 0;
  template <class T>
  T get() {
    if (at + sizeof(T) > in.size()) throw TetgenError(-1, "TetGen's result arrived truncated");
    T value;
    std::memcpy(&value, in.data() + at, sizeof value);
    at += sizeof value;
    return value;
  }
  template <class T>
  std::vector<T> get_vector() {
    const auto n = get<std::uint64_t>();
    if (n > (in.size() - at) / sizeof(T)) throw TetgenError(-1, "TetGen's result arrived truncated");
    std::vector<T> v(n);
    if (n > 0) std::memcpy(v.data(), in.data() + at, n * sizeof(T));
    at += n * sizeof(T);
    return v;
  }
};

constexpr char kOk = 0, kTetgenCode = 1, kOtherError = 2;

// `size`: null, or the field whose TetGen -m sizes the points get (`shift` added back to them).
void fill_tetgenio(const SurfacePlc& plc, const SizeField* size, const Vec3& shift, tetgenio& in) {
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(plc.points.size());
  in.pointlist = new REAL[3 * plc.points.size()];
  for (std::size_t i = 0; i < plc.points.size(); ++i)
    for (int d = 0; d < 3; ++d) in.pointlist[3 * i + d] = plc.points[i][d];
  if (size) {
    in.numberofpointmtrs = 1;
    in.pointmtrlist = new REAL[plc.points.size()];
    for (std::size_t i = 0; i < plc.points.size(); ++i)
      in.pointmtrlist[i] = kTetgenSizePerLength * (*size)(plc.points[i] + shift);
  }
  in.numberoffacets = static_cast<int>(plc.facets.size());
  in.facetlist = new tetgenio::facet[plc.facets.size()];
  in.facetmarkerlist = new int[plc.facets.size()];
  for (std::size_t f = 0; f < plc.facets.size(); ++f) {
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::polygon& polygon = facet.polygonlist[0];
    tetgenio::init(&polygon);
    polygon.numberofvertices = static_cast<int>(plc.facets[f].size());
    polygon.vertexlist = new int[plc.facets[f].size()];
    for (std::size_t k = 0; k < plc.facets[f].size(); ++k) polygon.vertexlist[k] = static_cast<int>(plc.facets[f][k]);
    in.facetmarkerlist[f] = plc.tags[f];
  }
  in.numberofholes = static_cast<int>(plc.holes.size());
  if (!plc.holes.empty()) {
    in.holelist = new REAL[3 * plc.holes.size()];
    for (std::size_t i = 0; i < plc.holes.size(); ++i)
      for (int d = 0; d < 3; ++d) in.holelist[3 * i + d] = plc.holes[i][d];
  }
}

// Tets positively oriented; boundary faces turned outward (away from the tet that owns them).
TetMesh from_tetgenio(const tetgenio& out) {
  TetMesh m;
  m.points.resize(static_cast<std::size_t>(out.numberofpoints));
  for (std::size_t i = 0; i < m.points.size(); ++i)
    m.points[i] = Vec3(out.pointlist[3 * i], out.pointlist[3 * i + 1], out.pointlist[3 * i + 2]);
  const auto n_tets = static_cast<std::size_t>(out.numberoftetrahedra);
  const int corners = out.numberofcorners;
  m.tets.resize(n_tets);
  m.tet_regions.assign(n_tets, 1);
  for (std::size_t t = 0; t < n_tets; ++t) {
    for (int c = 0; c < 4; ++c) m.tets[t][c] = static_cast<std::uint32_t>(out.tetrahedronlist[corners * t + c]);
    if (tet_volume(m, t) < 0) std::swap(m.tets[t][2], m.tets[t][3]);
  }
  // vertex -> incident tets (CSR), to find each boundary face's tet
  std::vector<std::uint32_t> start(m.points.size() + 1, 0), incident(4 * n_tets);
  for (const auto& t : m.tets)
    for (auto v : t) ++start[v + 1];
  for (std::size_t v = 0; v < m.points.size(); ++v) start[v + 1] += start[v];
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::uint32_t t = 0; t < n_tets; ++t)
    for (auto v : m.tets[t]) incident[fill[v]++] = t;
  const auto n_faces = static_cast<std::size_t>(out.numberoftrifaces);
  for (std::size_t f = 0; f < n_faces; ++f) {
    Triangle tri{static_cast<std::uint32_t>(out.trifacelist[3 * f]), static_cast<std::uint32_t>(out.trifacelist[3 * f + 1]),
                 static_cast<std::uint32_t>(out.trifacelist[3 * f + 2])};
    for (std::uint32_t k = start[tri[0]]; k < start[tri[0] + 1]; ++k) {
      const Tetrahedron& t = m.tets[incident[k]];
      auto has = [&](std::uint32_t v) { return t[0] == v || t[1] == v || t[2] == v || t[3] == v; };
      if (!has(tri[1]) || !has(tri[2])) continue;
      std::uint32_t apex = t[0];
      for (auto v : t)
        if (v != tri[0] && v != tri[1] && v != tri[2]) apex = v;
      const Vec3 &a = m.points[tri[0]], &b = m.points[tri[1]], &c = m.points[tri[2]];
      if ((b - a).cross(c - a).dot(m.points[apex] - a) > 0) std::swap(tri[1], tri[2]);
      break;
    }
    m.boundary_faces.push_back(tri);
    m.boundary_tags.push_back(out.trifacemarkerlist ? out.trifacemarkerlist[f] : 1);
  }
  return m;
}

std::string serialise(const TetMesh& m) {
  std::string out(1, kOk);
  std::vector<double> coordinates;
  coordinates.reserve(3 * m.points.size());
  for (const Vec3& p : m.points) coordinates.insert(coordinates.end(), {p.x(), p.y(), p.z()});
  put_vector(out, coordinates);
  put_vector(out, m.tets);
  put_vector(out, m.tet_regions);
  put_vector(out, m.boundary_faces);
  put_vector(out, m.boundary_tags);
  put_vector(out, m.tet_edge_nodes);  // empty: TetGen runs without -o2, but the message carries a whole TetMesh
  return out;
}

TetMesh deserialise(Reader& in) {
  TetMesh m;
  const std::vector<double> coordinates = in.get_vector<double>();
  for (std::size_t i = 0; i + 2 < coordinates.size(); i += 3)
    m.points.emplace_back(coordinates[i], coordinates[i + 1], coordinates[i + 2]);
  m.tets = in.get_vector<Tetrahedron>();
  m.tet_regions = in.get_vector<int>();
  m.boundary_faces = in.get_vector<Triangle>();
  m.boundary_tags = in.get_vector<int>();
  m.tet_edge_nodes = in.get_vector<TetEdgeNodes>();
  return m;
}

// Runs in the child process.
// With a size field (where the points lie once `shift` is added back), two
// runs: TetGen interpolates a Steiner point's size linearly from the tet it lands in, so from the
// surface's points alone the interior would get their blend, not the field (a field fine at one
// corner of a cube, coarse at the others: 70 % of the edges within [0.7, 1.4] h); the first run's
// tets, their points sized by the field, are the second's background mesh (TetGen's -m with a
// .b mesh), which carries the field inside.
std::string run_tetgen(const SurfacePlc& plc, const SizeField* size, const Vec3& shift, const std::string& switches) {
  try {
    tetgenio in, out;
    fill_tetgenio(plc, size, shift, in);
    std::string sw = switches;
    if (size) {
      tetgenio background;
      ::tetrahedralize(sw.data(), &in, &background);
      delete[] background.pointmtrlist;
      background.numberofpointmtrs = 1;
      background.pointmtrlist = new REAL[static_cast<std::size_t>(background.numberofpoints)];
      for (int i = 0; i < background.numberofpoints; ++i) {
        const REAL* p = background.pointlist + 3 * i;
        background.pointmtrlist[i] = kTetgenSizePerLength * (*size)(Vec3(p[0], p[1], p[2]) + shift);
      }
      sw = switches;
      ::tetrahedralize(sw.data(), &in, &out, nullptr, &background);
    } else {
      ::tetrahedralize(sw.data(), &in, &out);
    }
    return serialise(from_tetgenio(out));
  } catch (int code) {
    std::string out(1, kTetgenCode);
    put(out, code);
    return out;
  } catch (const std::exception& e) {
    return std::string(1, kOtherError) + e.what();
  }
}

}  // namespace

void check_tet_params(const TetParams& params) {
  const auto refuse = [](const char* field, const char* range, double value) {
    std::ostringstream message;
    message << "tetrahedralize: " << field << " must be " << range << ", not " << value;
    throw InvalidInput(message.str());
  };
  const double q = params.radius_edge;
  if (!(q == 0 || (q >= 1 && q <= 100)))
    refuse("radius_edge", "0 (no refinement) or in [1, 100] (TetGen's refinement need not end below 1)", q);
  if (!(params.min_dihedral_deg >= 0 && params.min_dihedral_deg <= 30))
    refuse("min_dihedral_deg", "in [0, 30]", params.min_dihedral_deg);
  if (!(params.max_volume >= 0 && std::isfinite(params.max_volume)))
    refuse("max_volume", "finite and >= 0", params.max_volume);
  if (!(params.max_volume_relative >= 0 && params.max_volume_relative <= 1))
    refuse("max_volume_relative", "in [0, 1]", params.max_volume_relative);
}

std::string tetgen_switches(const TetParams& params, double enclosed_volume) {
  check_tet_params(params);
  std::ostringstream sw;
  sw.precision(8);
  sw << "pzQ";  // PLC input, zero-based numbering, quiet
  if (params.radius_edge > 0) {
    sw << 'q' << params.radius_edge;
    if (params.min_dihedral_deg > 0) sw << '/' << params.min_dihedral_deg;
  }
  double max_volume = params.max_volume;
  if (params.max_volume_relative > 0) max_volume = params.max_volume_relative * enclosed_volume;
  if (max_volume > 0) sw << 'a' << max_volume;
  if (params.keep_surface) sw << 'Y';
  if (params.size_field) sw << 'm';
  return sw.str();
}

namespace {

// A point inside each component that encloses negative volume (a void's wall, facing into it):
// just off its widest face, on the side the face looks to (point_off_face).
std::vector<Vec3> void_points(const TriangleSoup& surface) {
  detail::UnionFind parts(surface.points.size());
  for (const Triangle& t : surface.triangles) parts.unite(t[0], t[1]), parts.unite(t[0], t[2]);
  std::map<std::uint32_t, double> volume;
  std::map<std::uint32_t, PointOffFace> widest;
  for (const Triangle& t : surface.triangles) {
    const Vec3 &a = surface.points[t[0]], &b = surface.points[t[1]], &c = surface.points[t[2]];
    const std::uint32_t part = parts.find(t[0]);
    volume[part] += a.dot(b.cross(c)) / 6;
    const PointOffFace off = point_off_face(a, b, c);
    if (off.inradius > widest[part].inradius) widest[part] = off;
  }
  std::vector<Vec3> holes;
  for (const auto& [part, v] : volume)
    if (v < 0 && widest[part].inradius > 0) holes.push_back(widest[part].point);
  return holes;
}

}  // namespace

SurfacePlc plc_from_surface(const TriangleSoup& surface, int tag) {
  constexpr std::uint32_t unused = ~std::uint32_t(0);
  std::vector<std::uint32_t> index(surface.points.size(), unused);
  for (const Triangle& t : surface.triangles)
    for (const std::uint32_t v : t) index[v] = 0;
  SurfacePlc plc;
  for (std::size_t v = 0; v < surface.points.size(); ++v) {
    if (index[v] == unused) continue;
    index[v] = static_cast<std::uint32_t>(plc.points.size());
    plc.points.push_back(surface.points[v]);
  }
  for (const Triangle& t : surface.triangles) plc.facets.push_back({index[t[0]], index[t[1]], index[t[2]]});
  if (surface.patches.empty()) plc.tags.assign(plc.facets.size(), tag);
  else plc.tags = surface.patches;
  plc.tag_names = surface.patch_names;
  plc.holes = void_points(surface);
  return plc;
}

namespace {

// The PLC's volume with every point moved by -shift.
double shifted_volume(const SurfacePlc& plc, const Vec3& shift) {
  double six_volume = 0;
  for (const auto& facet : plc.facets) {
    const Vec3 a = plc.points[facet[0]] - shift;
    for (std::size_t k = 1; k + 1 < facet.size(); ++k)
      six_volume += a.dot((plc.points[facet[k]] - shift).cross(plc.points[facet[k + 1]] - shift));
  }
  return six_volume / 6.0;
}

}  // namespace

double plc_volume(const SurfacePlc& plc) { return shifted_volume(plc, Vec3::Zero()); }

double volume_change_relative(const SurfacePlc& plc, const TetMesh& tets) {
  // Both next to the origin, where the products keep the shape's bits (origin_shift.h).
  const Vec3 shift = origin_shift(plc.points);
  const double enclosed = shifted_volume(plc, shift);
  double volume = 0;
  for (const Tetrahedron& t : tets.tets) {
    const Vec3 a = tets.points[t[0]] - shift;
    volume += (tets.points[t[1]] - shift - a).dot((tets.points[t[2]] - shift - a).cross(tets.points[t[3]] - shift - a)) / 6.0;
  }
  return (volume - enclosed) / enclosed;
}

std::string volume_change_note(double change) {
  if (!(std::abs(change) > kVolumeKeptRelative)) return {};
  std::ostringstream note;
  note.precision(3);
  note << "the tets' volume differs from the surface's by " << change
       << " of it: without keep-surface TetGen treats neighbouring facets within 0.1 deg of flat as one and may "
          "retriangulate across their edge (--keep-surface keeps the surface exactly)";
  return note.str();
}

TetMesh tetrahedralize_plc(const SurfacePlc& surface, const TetParams& params) {
  // TetGen's Steiner points, tolerances and our enclosed volume (the cones below) are computed in
  // absolute coordinates: far from the origin TetGen gets the surface moved next to it.
  const Vec3 shift = origin_shift(surface.points);
  SurfacePlc moved;
  if (!shift.isZero()) {
    moved = surface;
    for (Vec3& p : moved.points) p -= shift;
    for (Vec3& p : moved.holes) p -= shift;
  }
  const SurfacePlc& plc = shift.isZero() ? surface : moved;
  const std::string switches = tetgen_switches(params, std::abs(plc_volume(plc)));
  const detail::IsolatedResult run =
      detail::call_isolated([&] { return run_tetgen(plc, params.size_field.get(), shift, switches); }, params.cancelled);
  if (run.crashed || run.output.empty()) {
    const std::string how = run.signal ? "signal " + std::to_string(run.signal) + ": " + strsignal(run.signal)
                                       : "exit status " + std::to_string(run.exit_status);
    throw TetgenError(-1, "TetGen crashed (" + how + ") on this surface; check it with `meshprep quality`");
  }
  Reader in{run.output, 1};
  switch (run.output[0]) {
    case kTetgenCode: {
      const int code = in.get<int>();
      throw TetgenError(code, explain_tetgen_code(code) + " (TetGen code " + std::to_string(code) + ")");
    }
    case kOtherError:
      throw TetgenError(2, "TetGen failed: " + run.output.substr(1));
    default:
      break;
  }
  TetMesh mesh = deserialise(in);
  for (Vec3& p : mesh.points) p += shift;
  mesh.boundary_names = surface.tag_names;
  if (mesh.tets.empty())
    throw TetgenError(0, "TetGen produced no tetrahedra: the surface does not enclose a volume (holes let the "
                         "exterior removal leak in)");
  return mesh;
}

}  // namespace meshprep
