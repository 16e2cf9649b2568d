// Abaqus / CalculiX input deck .inp with linear tetrahedra (C3D4) or second-order ones (C3D10),
// 1-based node and element ids
// (tet t is element t + 1):
//   *NODE; one *ELEMENT, TYPE=C3D4 (or C3D10), ELSET=<region> block per region;
//   per boundary tag: *NSET (the nodes of its faces, mid-edge nodes included), *ELSET (the tets having a face on it) and an
//   element-face surface *SURFACE, TYPE=ELEMENT with "element, S<k>" lines.
// Names: a region's element set is named by TetMesh::region_names, else REGION_<r>. A patch
// named in TetMesh::boundary_names gives its name to its node set and its surface, which *BOUNDARY
// and *DSLOAD take, and <name>_TETS to its element set (the name cut so that this fits
// kMaxNameLength); an unnamed tag keeps the names decks written before patches had names refer to:
// BOUNDARY_<t> (node and element set) and SURF_<t> (surface).
// Why not one name for all three: CalculiX 2.20 dies with a segmentation fault on a *DSLOAD on an
// element-face surface that shares its name with an element set (a node set may share it).
// Element sets and surfaces therefore form one namespace, node sets another; Abaqus and CalculiX
// ignore the case of names, and a name given twice in one namespace is refused (naming both
// owners). (write_tet_mesh has refused a name against patch_names.h's rule, which a comma or a
// space would break out of the keyword's parameter.)
// Data lines hold at most 16 entries (the Abaqus limit for set definitions).
//
// Numbers: CalculiX (2.20) reads each field of a data line into 20 characters and stops with
// "*ERROR reading *NODE" on a longer one, while a double's shortest round-trip form takes up to 24
// ("-1.2345678901234567e-100"). A coordinate is written in that form when it fits, else with the
// most significant digits whose general form fits (13 at the least, a relative rounding under
// 5e-13), and the rounding is reported (TetExportReport).
//
// Orientation: C3D4 nodes 1-2-3 are counter-clockwise seen from node 4, i.e. positive volume in
// TetMesh's sense, so tets are written in their own order. Faces (Abaqus Analysis User's Guide,
// "Three-dimensional solid element library"; CalculiX manual, C3D4): S1 = 1-2-3, S2 = 1-4-2,
// S3 = 2-4-3, S4 = 3-4-1, each listed with its normal pointing into the element.
//
// C3D10: corners 1-4 as C3D4's, then nodes 5-10 on edges 1-2, 2-3, 3-1, 1-4, 2-4, 3-4 (Abaqus
// Analysis User's Guide, "Three-dimensional solid element library", node ordering figure;
// CalculiX CrunchiX manual, "Ten-node tetrahedral element (C3D10)"): kTetEdges' order, checked
// on what `gmsh -3 -order 2` writes to .inp. Its faces are numbered as C3D4's, so the surfaces
// are written alike.
#include "exporters.h"
#include "tet_faces.h"
#include "text_buffer.h"

#include "meshprep/core/atomic_file.h"
#include "meshprep/core/errors.h"
#include "meshprep/core/patch_names.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace meshprep::detail {
namespace {

constexpr std::size_t max_entries_per_line = 16;
constexpr std::size_t max_field_length = 20;

// C3D4's face number of the face opposite each corner: S1 = 1-2-3 is opposite corner 4, S2 = 1-4-2
// opposite 3, S3 = 2-4-3 opposite 1, S4 = 3-4-1 opposite 2 (0-based: corner 0 -> S3, ...).
constexpr std::array<int, 4> c3d4_face_opposite{3, 4, 2, 1};

struct FaceOwner {
  std::size_t tet;
  int face;  // 1..4 for S1..S4
};

// For each (outward) boundary face, the tet having it as an outward face and the face's number.
std::vector<FaceOwner> face_owners(const TetMesh& mesh, const std::string& path) {
  const std::vector<std::uint32_t> tet_faces = tet_faces_of(mesh.tets, mesh.boundary_faces);
  std::vector<FaceOwner> owners(mesh.boundary_faces.size());
  for (std::size_t f = 0; f < owners.size(); ++f) {
    const std::uint32_t tet_face = tet_faces[f];
    if (tet_face == kNoTetFace || !same_orientation(mesh.boundary_faces[f],
                                                    face_of(mesh.tets[tet_face / 4], static_cast<int>(tet_face % 4))))
      throw InvalidInput(path + ": cannot export: boundary face " + std::to_string(f) +
                         " is not an outward face of any tetrahedron (needed for the *SURFACE)");
    owners[f] = {tet_face / 4, c3d4_face_opposite[tet_face % 4]};
  }
  return owners;
}

std::map<int, std::vector<std::size_t>> group_by_tag(const std::vector<int>& tags) {
  std::map<int, std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < tags.size(); ++i) groups[tags[i]].push_back(i);
  return groups;
}

// Comma-separated, at most max_entries_per_line per line.
void write_id_list(TextBuffer& out, const std::vector<std::size_t>& ids) {
  for (std::size_t i = 0; i < ids.size(); ++i) {
    out << ids[i];
    const bool line_end = (i + 1) % max_entries_per_line == 0 || i + 1 == ids.size();
    out << (line_end ? "\n" : ", ");
  }
}

// `value` in at most max_field_length characters: the shortest round-trip form if it fits, else
// the general form with the most significant digits that fits; a rounding goes into `report`.
void write_field(TextBuffer& out, double value, TetExportReport& report) {
  std::array<char, 32> buffer;  // the longest shortest-round-trip double is 24 characters
  char* const first = buffer.data();
  char* last = std::to_chars(first, first + buffer.size(), value).ptr;
  if (static_cast<std::size_t>(last - first) > max_field_length) {
    for (int precision = std::numeric_limits<double>::max_digits10 - 1; precision > 0; --precision) {
      last = std::to_chars(first, first + buffer.size(), value, std::chars_format::general, precision).ptr;
      if (static_cast<std::size_t>(last - first) <= max_field_length) break;
    }
    double written = 0;
    std::from_chars(first, last, written);
    ++report.rounded_coordinates;
    report.max_relative_rounding = std::max(report.max_relative_rounding, std::abs(written - value) / std::abs(value));
  }
  out << std::string_view(first, static_cast<std::size_t>(last - first));
}

void write_nodes(TextBuffer& out, const TetMesh& mesh, TetExportReport& report) {
  out << "*NODE\n";
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    out << v + 1;
    for (int c = 0; c < 3; ++c) {
      out << ", ";
      write_field(out, mesh.points[v][c], report);
    }
    out << '\n';
  }
}

// The names of the sets: a region's element set; a patch's node set, element set and surface.
struct SetNames {
  std::map<int, std::string> region;
  std::map<int, std::string> patch_nset, patch_elset, patch_surface;
};

constexpr char kPatchElsetSuffix[] = "_TETS";

std::string upper_case(std::string name) {
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return name;
}

// Refuses a name given twice in one namespace (`sets`: each set's owner, and its name).
void check_distinct(const std::string& path, const std::vector<std::pair<std::string, std::string>>& sets) {
  std::map<std::string, const std::string*> owners;  // upper-case name -> owner
  for (const auto& [owner, name] : sets) {
    const auto [it, inserted] = owners.emplace(upper_case(name), &owner);
    if (!inserted)
      throw InvalidInput(path + ": cannot export: " + name + " would name both " + *it->second + " and " + owner +
                         " (names ignore case, and CalculiX cannot tell an element set from a surface of the same "
                         "name); rename one");
  }
}

SetNames set_names(const TetMesh& mesh, const std::string& path) {
  SetNames names;
  std::vector<std::pair<std::string, std::string>> elsets_and_surfaces, nsets;
  for (int region : distinct_tags(mesh.tet_regions)) {
    names.region[region] = tag_name(mesh.region_names, region, "REGION");
    elsets_and_surfaces.emplace_back("the ELSET of region " + std::to_string(region), names.region[region]);
  }
  for (int tag : distinct_tags(mesh.boundary_tags)) {
    const auto named = mesh.boundary_names.find(tag);
    const std::string number = std::to_string(tag);
    if (named != mesh.boundary_names.end()) {
      const std::string& name = named->second;
      names.patch_nset[tag] = names.patch_surface[tag] = name;
      names.patch_elset[tag] = name.substr(0, kMaxNameLength - (sizeof kPatchElsetSuffix - 1)) + kPatchElsetSuffix;
    } else {
      names.patch_nset[tag] = names.patch_elset[tag] = "BOUNDARY_" + number;
      names.patch_surface[tag] = "SURF_" + number;
    }
    nsets.emplace_back("the NSET of boundary tag " + number, names.patch_nset[tag]);
    elsets_and_surfaces.emplace_back("the ELSET of boundary tag " + number, names.patch_elset[tag]);
    elsets_and_surfaces.emplace_back("the SURFACE of boundary tag " + number, names.patch_surface[tag]);
  }
  check_distinct(path, elsets_and_surfaces);
  check_distinct(path, nsets);
  return names;
}

// Sorted, each once, 1-based.
std::vector<std::size_t> distinct_ids(std::vector<std::size_t> ids) {
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  for (std::size_t& id : ids) ++id;
  return ids;
}

const char* element_type(const TetMesh& mesh) { return mesh.quadratic() ? "C3D10" : "C3D4"; }

// One line per element: 11 entries at most for C3D10, within the 16 of a data line.
void write_elements(TextBuffer& out, const TetMesh& mesh, const SetNames& names) {
  for (const auto& [region, tets] : group_by_tag(mesh.tet_regions)) {
    out << "*ELEMENT, TYPE=" << element_type(mesh) << ", ELSET=" << names.region.at(region) << '\n';
    for (std::size_t t : tets) {
      out << t + 1;
      for (std::uint32_t v : mesh.tets[t]) out << ", " << v + std::size_t{1};
      if (mesh.quadratic())
        for (std::uint32_t v : mesh.tet_edge_nodes[t]) out << ", " << v + std::size_t{1};
      out << '\n';
    }
  }
}

void write_boundaries(TextBuffer& out, const TetMesh& mesh, const std::vector<FaceOwner>& owners,
                      const SetNames& names) {
  const std::vector<std::array<std::uint32_t, 3>> face_nodes = boundary_face_edge_nodes(mesh);
  for (const auto& [tag, faces] : group_by_tag(mesh.boundary_tags)) {
    std::vector<std::size_t> nodes, tets;
    for (std::size_t f : faces) {
      for (std::uint32_t v : mesh.boundary_faces[f]) nodes.push_back(v);
      if (mesh.quadratic())
        for (std::uint32_t v : face_nodes[f]) nodes.push_back(v);
      tets.push_back(owners[f].tet);
    }
    out << "*NSET, NSET=" << names.patch_nset.at(tag) << '\n';
    write_id_list(out, distinct_ids(std::move(nodes)));
    out << "*ELSET, ELSET=" << names.patch_elset.at(tag) << '\n';
    write_id_list(out, distinct_ids(std::move(tets)));
    out << "*SURFACE, NAME=" << names.patch_surface.at(tag) << ", TYPE=ELEMENT\n";
    for (std::size_t f : faces) out << owners[f].tet + 1 << ", S" << owners[f].face << '\n';
  }
}

}  // namespace

void write_abaqus(const TetMesh& mesh, const std::string& path, TetExportReport& report) {
  const std::vector<FaceOwner> owners = face_owners(mesh, path);
  const SetNames names = set_names(mesh, path);
  write_file_atomically(path, [&](std::ostream& stream) {
    report = {};
    TextBuffer out(stream);
    out << "*HEADING\n"
        << "meshprep tetrahedral mesh: " << mesh.points.size() << " nodes, " << mesh.tets.size() << ' ' << element_type(mesh) << " elements\n";
    write_nodes(out, mesh, report);
    write_elements(out, mesh, names);
    write_boundaries(out, mesh, owners, names);
    out.flush();
  });
}

}  // namespace meshprep::detail
