// Gmsh .msh 4.1 and 2.2, ASCII and binary (Gmsh reference manual, "MSH file format" and "MSH file
// format version 2 (Legacy)"; https://gmsh.info/doc/texinfo/gmsh.html#MSH-file-format).
//
// Orientation: Gmsh's reference 4-node tetrahedron (element type 4) is (0,0,0) (1,0,0) (0,1,0)
// (0,0,1), i.e. positive volume in TetMesh's sense, so tets are written in their own order.
// Triangles (element type 2) keep their outward orientation.
//
// Second order: 10-node tets (type 11) and 6-node triangles (type 9), in Gmsh's node order
// (gmsh_elements.h).
//
// Tags: physical and elementary tags are the region for tets and the boundary tag for triangles;
// the physical names are the mesh's names of them (region_<r> and boundary_<t> where it has none).
// In 4.1 there is one discrete volume entity per region and one discrete surface entity per
// boundary tag (entity tag = physical tag, no bounding entities); in 2.2 each element carries
// the two tags (physical, elementary). Element tags: tet t is t + 1, boundary face f is T + f + 1.
#include "exporters.h"
#include "gmsh_elements.h"

#include "meshprep/core/atomic_file.h"
#include "meshprep/core/patch_names.h"

#include <cstdint>
#include <cstring>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace meshprep::detail {
namespace {

// The elements as Gmsh lists their nodes (the writers below take either): a linear mesh's own
// tets and boundary faces, or a second-order mesh's 10-node tets and 6-node triangles.
struct LinearElements {
  const std::vector<Tetrahedron>& tets;
  const std::vector<Triangle>& faces;
  int tet_type, face_type;
};

struct SecondOrderElements {
  std::vector<std::array<std::uint32_t, 10>> tets;
  std::vector<std::array<std::uint32_t, 6>> faces;
  int tet_type, face_type;
};

SecondOrderElements second_order_elements(const TetMesh& mesh) {
  SecondOrderElements elements{{}, {}, gmsh_tetrahedron_10, gmsh_triangle_6};
  elements.tets.resize(mesh.tets.size());
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    std::copy(mesh.tets[t].begin(), mesh.tets[t].end(), elements.tets[t].begin());
    for (int k = 0; k < 6; ++k) elements.tets[t][4 + k] = mesh.tet_edge_nodes[t][kGmshTetEdges[k]];
  }
  elements.faces = with_nodes(mesh.boundary_faces, boundary_face_edge_nodes(mesh));
  return elements;
}

// The numbers of a section: text separated by spaces (ASCII), or raw native-endian values
// (binary: int = 4 bytes, size_t = 8 bytes as declared by data-size 8, double = 8 bytes; the int 1
// after the header lets readers check the byte order).
class MshStream {
 public:
  MshStream(std::ostream& out, bool binary) : out_(out), binary_(binary) {}

  void size(std::size_t value) { put(static_cast<std::uint64_t>(value)); }
  void integer(std::int64_t value) { put(static_cast<std::int32_t>(value)); }
  void real(double value) {
    if (binary_) return put(value);
    separate();
    write_real(out_, value);
  }
  void end_line() {
    if (!binary_) out_ << '\n';
    line_start_ = true;
  }
  // Binary data is followed by a newline before the section's end marker.
  void end_section(const char* name) {
    if (binary_) out_ << '\n';
    out_ << "$End" << name << '\n';
  }

 private:
  template <class T>
  void put(T value) {
    if (binary_) {
      char bytes[sizeof(T)];
      std::memcpy(bytes, &value, sizeof(T));
      out_.write(bytes, sizeof(T));
    } else {
      separate();
      out_ << value;
    }
  }
  void separate() {
    if (!line_start_) out_ << ' ';
    line_start_ = false;
  }

  std::ostream& out_;
  bool binary_;
  bool line_start_ = true;
};

void write_header(std::ostream& out, const char* version, bool binary) {
  out << "$MeshFormat\n" << version << (binary ? " 1 8\n" : " 0 8\n");
  if (binary) {
    MshStream(out, true).integer(1);
    out << '\n';
  }
  out << "$EndMeshFormat\n";
}

// Always ASCII, also in binary files.
void write_physical_names(std::ostream& out, const TetMesh& mesh) {
  const std::vector<int> surfaces = distinct_tags(mesh.boundary_tags);
  const std::vector<int> volumes = distinct_tags(mesh.tet_regions);
  out << "$PhysicalNames\n" << surfaces.size() + volumes.size() << '\n';
  for (int tag : surfaces) out << "2 " << tag << " \"" << tag_name(mesh.boundary_names, tag, "boundary") << "\"\n";
  for (int region : volumes) out << "3 " << region << " \"" << tag_name(mesh.region_names, region, "region") << "\"\n";
  out << "$EndPhysicalNames\n";
}

// ---- MSH 4.1 ----

// A discrete entity: a surface (one boundary tag) or a volume (one region).
struct Entity {
  int dim;
  int tag;
  std::vector<std::size_t> elements;  // boundary face or tet indices
  std::vector<std::uint32_t> nodes;   // the nodes classified on this entity
  Eigen::AlignedBox3d box;
};

template <std::size_t N>
void add_elements(std::vector<Entity>& entities, const std::map<int, std::size_t>& entity_of,
                  const std::vector<std::array<std::uint32_t, N>>& elements, const std::vector<int>& tags,
                  const TetMesh& mesh) {
  for (std::size_t e = 0; e < elements.size(); ++e) {
    Entity& entity = entities[entity_of.at(tags[e])];
    entity.elements.push_back(e);
    for (std::uint32_t v : elements[e]) entity.box.extend(mesh.points[v]);
  }
}

// Surfaces (ascending boundary tag) then volumes (ascending region). Each node is classified on
// the surface of the first boundary face using it, else the volume of the first tet using it
// (nodes used by nothing go to the first volume).
template <class Elements>
std::vector<Entity> make_entities(const TetMesh& mesh, const Elements& elements) {
  std::vector<Entity> entities;
  std::map<int, std::size_t> surface_of;
  std::map<int, std::size_t> volume_of;
  for (int tag : distinct_tags(mesh.boundary_tags)) {
    surface_of[tag] = entities.size();
    entities.push_back({2, tag, {}, {}, {}});
  }
  for (int region : distinct_tags(mesh.tet_regions)) {
    volume_of[region] = entities.size();
    entities.push_back({3, region, {}, {}, {}});
  }
  add_elements(entities, surface_of, elements.faces, mesh.boundary_tags, mesh);
  add_elements(entities, volume_of, elements.tets, mesh.tet_regions, mesh);

  const std::size_t unclassified = entities.size();
  std::vector<std::size_t> node_entity(mesh.points.size(), unclassified);
  auto classify = [&](const auto& vertices, std::size_t entity) {
    for (std::uint32_t v : vertices)
      if (node_entity[v] == unclassified) node_entity[v] = entity;
  };
  for (std::size_t f = 0; f < elements.faces.size(); ++f)
    classify(elements.faces[f], surface_of.at(mesh.boundary_tags[f]));
  for (std::size_t t = 0; t < elements.tets.size(); ++t) classify(elements.tets[t], volume_of.at(mesh.tet_regions[t]));
  for (std::uint32_t v = 0; v < mesh.points.size(); ++v) {
    Entity& entity = entities[node_entity[v] == unclassified ? surface_of.size() : node_entity[v]];
    entity.nodes.push_back(v);
  }
  return entities;
}

void write_entities_41(MshStream& s, const std::vector<Entity>& entities, std::size_t num_surfaces) {
  s.size(0);  // points
  s.size(0);  // curves
  s.size(num_surfaces);
  s.size(entities.size() - num_surfaces);
  s.end_line();
  for (const Entity& entity : entities) {
    // tag, bounding box, physical tags, bounding entities (none: discrete entities)
    s.integer(entity.tag);
    for (double c : {entity.box.min().x(), entity.box.min().y(), entity.box.min().z(), entity.box.max().x(),
                     entity.box.max().y(), entity.box.max().z()})
      s.real(c);
    s.size(1);
    s.integer(entity.tag);
    s.size(0);
    s.end_line();
  }
}

void write_nodes_41(MshStream& s, const TetMesh& mesh, const std::vector<Entity>& entities) {
  std::size_t num_blocks = 0;
  for (const Entity& entity : entities) num_blocks += entity.nodes.empty() ? 0 : 1;
  s.size(num_blocks);
  s.size(mesh.points.size());
  s.size(1);
  s.size(mesh.points.size());
  s.end_line();
  for (const Entity& entity : entities) {
    if (entity.nodes.empty()) continue;
    s.integer(entity.dim);
    s.integer(entity.tag);
    s.integer(0);  // no parametric coordinates
    s.size(entity.nodes.size());
    s.end_line();
    for (std::uint32_t v : entity.nodes) {
      s.size(v + std::size_t{1});
      s.end_line();
    }
    for (std::uint32_t v : entity.nodes) {
      for (int c = 0; c < 3; ++c) s.real(mesh.points[v][c]);
      s.end_line();
    }
  }
}

template <std::size_t N>
void write_element_block_41(MshStream& s, const Entity& entity, int type, std::size_t first_tag,
                            const std::vector<std::array<std::uint32_t, N>>& elements) {
  s.integer(entity.dim);
  s.integer(entity.tag);
  s.integer(type);
  s.size(entity.elements.size());
  s.end_line();
  for (std::size_t e : entity.elements) {
    s.size(first_tag + e);
    for (std::uint32_t v : elements[e]) s.size(v + std::size_t{1});
    s.end_line();
  }
}

template <class Elements>
void write_elements_41(MshStream& s, const TetMesh& mesh, const Elements& elements, const std::vector<Entity>& entities) {
  const std::size_t num_elements = mesh.tets.size() + mesh.boundary_faces.size();
  s.size(entities.size());
  s.size(num_elements);
  s.size(1);
  s.size(num_elements);
  s.end_line();
  for (const Entity& entity : entities) {
    if (entity.dim == 2)
      write_element_block_41(s, entity, elements.face_type, mesh.tets.size() + 1, elements.faces);
    else
      write_element_block_41(s, entity, elements.tet_type, 1, elements.tets);
  }
}

template <class Elements>
void write_msh41(std::ostream& out, const TetMesh& mesh, const Elements& elements, bool binary) {
  const std::vector<Entity> entities = make_entities(mesh, elements);
  const std::size_t num_surfaces = distinct_tags(mesh.boundary_tags).size();
  MshStream s(out, binary);
  write_header(out, "4.1", binary);
  write_physical_names(out, mesh);
  out << "$Entities\n";
  write_entities_41(s, entities, num_surfaces);
  s.end_section("Entities");
  out << "$Nodes\n";
  write_nodes_41(s, mesh, entities);
  s.end_section("Nodes");
  out << "$Elements\n";
  write_elements_41(s, mesh, elements, entities);
  s.end_section("Elements");
}

// ---- MSH 2.2 ----
// The counts after $Nodes and $Elements are ASCII lines in both modes. ASCII element lines are
// "number type num-tags tags... nodes..."; binary data is grouped under a header
// (type, number of elements, num-tags) and each element is "number tags... nodes...".

void write_nodes_22(std::ostream& out, MshStream& s, const TetMesh& mesh) {
  out << "$Nodes\n" << mesh.points.size() << '\n';
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    s.integer(static_cast<std::int64_t>(v + 1));
    for (int c = 0; c < 3; ++c) s.real(mesh.points[v][c]);
    s.end_line();
  }
  s.end_section("Nodes");
}

template <std::size_t N>
void write_element_group_22(MshStream& s, bool binary, int type, std::size_t first_number,
                            const std::vector<std::array<std::uint32_t, N>>& elements, const std::vector<int>& tags) {
  if (elements.empty()) return;
  constexpr int num_tags = 2;  // physical, elementary
  if (binary) {
    s.integer(type);
    s.integer(static_cast<std::int64_t>(elements.size()));
    s.integer(num_tags);
  }
  for (std::size_t e = 0; e < elements.size(); ++e) {
    s.integer(static_cast<std::int64_t>(first_number + e));
    if (!binary) {
      s.integer(type);
      s.integer(num_tags);
    }
    s.integer(tags[e]);
    s.integer(tags[e]);
    for (std::uint32_t v : elements[e]) s.integer(std::int64_t{v} + 1);
    s.end_line();
  }
}

template <class Elements>
void write_msh22(std::ostream& out, const TetMesh& mesh, const Elements& elements, bool binary) {
  MshStream s(out, binary);
  write_header(out, "2.2", binary);
  write_physical_names(out, mesh);
  write_nodes_22(out, s, mesh);
  out << "$Elements\n" << mesh.tets.size() + mesh.boundary_faces.size() << '\n';
  write_element_group_22(s, binary, elements.tet_type, 1, elements.tets, mesh.tet_regions);
  write_element_group_22(s, binary, elements.face_type, mesh.tets.size() + 1, elements.faces, mesh.boundary_tags);
  s.end_section("Elements");
}

template <class Elements>
void write_gmsh_elements(const TetMesh& mesh, const Elements& elements, const std::string& path,
                         const TetExportOptions& options) {
  write_file_atomically(
      path,
      [&](std::ostream& out) {
        if (options.msh_version == MshVersion::V22)
          write_msh22(out, mesh, elements, options.binary);
        else
          write_msh41(out, mesh, elements, options.binary);
      },
      options.binary);
}

}  // namespace

void write_gmsh(const TetMesh& mesh, const std::string& path, const TetExportOptions& options) {
  if (mesh.quadratic())
    write_gmsh_elements(mesh, second_order_elements(mesh), path, options);
  else  // the mesh's own arrays, not copied
    write_gmsh_elements(mesh, LinearElements{mesh.tets, mesh.boundary_faces, gmsh_tetrahedron, gmsh_triangle}, path, options);
}

}  // namespace meshprep::detail
