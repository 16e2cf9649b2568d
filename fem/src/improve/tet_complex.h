#pragma once
// The tet mesh as the improvement edits it: tets with their face neighbours, which faces are
// constrained (the boundary, faces between regions, faces the mesh lists as boundary faces),
// which vertices may move, and each tet's quality. Every edit goes through replace(), which
// proves that the new tets fill exactly the space of the old ones before it changes anything.

#include "meshprep/fem/tet_mesh.h"

#include <cstdint>
#include <vector>

namespace meshprep::improve {

using TetId = std::uint32_t;
using VertexId = std::uint32_t;
constexpr TetId kNoTet = ~TetId(0);

class TetComplex {
 public:
  /// \pre every tet of `mesh` references existing points (check_tet_mesh_structure).
  /// \throws InvalidInput if a face is shared by more than two tets, or two tets sharing a face
  ///         are oriented inconsistently (they overlap); Cancelled when `cancelled` (asked once per
  ///         block of tets, from any thread) says so.
  TetComplex(const TetMesh& mesh, double obtuse_weight, const std::function<bool()>& cancelled = {});

  std::size_t tet_slots() const { return tets_.size(); }
  std::size_t live_tets() const { return tets_.size() - free_slots_.size(); }
  bool alive(TetId t) const { return alive_[t] != 0; }
  const Tetrahedron& tet(TetId t) const { return tets_[t]; }
  int region(TetId t) const { return regions_[t]; }
  double quality(TetId t) const { return quality_[t]; }
  /// The tet across the face opposite corner `corner` of t, or kNoTet on the boundary.
  TetId neighbour(TetId t, int corner) const { return neighbours_[t][corner]; }
  bool constrained(TetId t, int corner) const { return (constrained_[t] >> corner) & 1u; }

  std::size_t points() const { return points_.size(); }
  const Vec3& point(VertexId v) const { return points_[v]; }
  /// Not on a constrained face: the vertex may move, and nothing about the boundary changes.
  bool free_vertex(VertexId v) const { return free_[v] != 0; }

  double obtuse_weight() const { return obtuse_weight_; }
  /// The objective of the tet (a, b, c, d) (tet_objective.h).
  double quality_of(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) const;
  double quality_of(const Tetrahedron& t) const;

  /// The tets that have v as a corner.
  void star(VertexId v, std::vector<TetId>& out) const;

  /// The tets around the edge (a, b) of tet t, in order, and the ring of their other corners:
  /// (a, b, ring[i], ring[i + 1]) is positively oriented and is tets[i]. False (and nothing
  /// useful in the outputs) when a face around the edge is constrained, which includes every
  /// edge on the boundary, or the ring has more than `max_ring` tets.
  bool edge_ring(TetId t, VertexId a, VertexId b, std::size_t max_ring, std::vector<TetId>& tets,
                 std::vector<VertexId>& ring) const;

  /// Replaces the tets `old` (live, one region) by `fresh` when the fresh tets are a valid
  /// triangulation of the same space: each is positive by the exact test, each face they share
  /// is shared by exactly two of them with opposite orientations, their other faces are exactly
  /// the old set's outer faces with the same orientation, and they use every corner of the old
  /// tets (so no vertex is lost). These make the new tets cover the old space once (the degree
  /// of the map is one everywhere); constrained faces, neighbours and the region are carried
  /// over. Returns false and changes nothing otherwise. With `slots`, fresh[k] takes the id
  /// slots[k], which must be free once the old tets are gone (to undo a replacement with the
  /// ids it freed: the inverse replacement then restores the mesh exactly).
  bool replace(const std::vector<TetId>& old, const std::vector<Tetrahedron>& fresh,
               const std::vector<TetId>* slots = nullptr);
  /// Like replace(), for the tets `star` of free vertex v, whose `fresh` tets no longer use v:
  /// v is removed (to_mesh leaves it out).
  bool remove_vertex(VertexId v, const std::vector<TetId>& star, const std::vector<Tetrahedron>& fresh);
  /// The tets the last successful replace() or remove_vertex() made.
  const std::vector<TetId>& created() const { return created_; }

  /// A new free vertex at p (no tet uses it until a replace() does).
  VertexId add_point(const Vec3& p);
  /// Takes back the point add_point just made. \pre v is the last point and no tet uses it.
  void discard_point(VertexId v);
  /// Moves vertex v to p and updates the qualities of its tets (`star`, from star()).
  /// \pre the caller checked that every tet of the star stays positive at p; a vertex on a
  /// constrained face moves only where the caller keeps the boundary's shape (boundary_slides.h).
  void move_point(VertexId v, const Vec3& p, const std::vector<TetId>& star);

  /// The mesh with the edits: the original points (unmoved ones bit for bit) then the added
  /// ones, without the removed ones (the others renumbered in order), the live tets in slot
  /// order, `original`'s boundary faces and tags.
  TetMesh to_mesh(const TetMesh& original) const;

 private:
  bool replace_tets(const std::vector<TetId>& old, const std::vector<Tetrahedron>& fresh,
                    const std::vector<TetId>* slots, VertexId removed);
  TetId new_slot();
  bool take_slot(TetId t);
  void link(TetId t, int corner, TetId other);

  std::vector<Vec3> points_;
  std::vector<std::uint8_t> free_;
  std::vector<std::uint8_t> removed_;  ///< removed by remove_vertex
  bool any_removed_ = false;
  std::vector<TetId> vertex_tet_;  ///< a tet with the vertex as a corner (kNoTet: none)
  std::vector<Tetrahedron> tets_;
  std::vector<std::array<TetId, 4>> neighbours_;
  std::vector<std::uint8_t> constrained_;  ///< bit c: the face opposite corner c
  std::vector<int> regions_;
  std::vector<double> quality_;
  std::vector<std::uint8_t> alive_;
  std::vector<TetId> free_slots_;
  std::vector<TetId> created_;
  double obtuse_weight_;
};

constexpr VertexId kNoVertex = ~VertexId(0);

/// The corners of tet t's face opposite corner c, ordered so that their normal points out of t.
std::array<VertexId, 3> outward_face(const Tetrahedron& t, int c);

}  // namespace meshprep::improve
