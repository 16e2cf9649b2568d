#include "enhance/sizing_field.h"

#include "shared/triangle_angles.h"

#include "meshprep/core/soup_view.h"
#include "meshprep/core/user_size_demands.h"
#include "meshprep/quality/surface_distance.h"
#include "meshprep/quality/triangle_metrics.h"

#include <algorithm>
#include <cmath>

namespace meshprep::detail {
namespace {

// A wall across counts for the thickness when its normal is within 30 degrees of facing back.
const double kOppositeWall = std::cos(30.0 * M_PI / 180.0);
// A piece of a face thinner than this fraction of its parent piece is near a wedge's edge (a
// plate keeps its thickness from piece to piece; toward a wedge's edge it halves with the piece).
constexpr double kWedgeThinning = 0.75;
// Area of an equilateral triangle of unit edge.
const double kEquilateralArea = std::sqrt(3.0) / 4.0;

// Curvature across an interior edge: the angle between its faces' normals over the width of the
// two faces across it (the mean of their heights over the edge); and that width.
std::pair<double, double> edge_curvature(const TriMesh& mesh, TriMesh::EdgeHandle e) {
  const auto f0 = mesh.face_handle(mesh.halfedge_handle(e, 0)), f1 = mesh.face_handle(mesh.halfedge_handle(e, 1));
  const double length = mesh.calc_edge_length(e);
  const Vec3 n0 = to_eigen(mesh.calc_face_normal(f0)), n1 = to_eigen(mesh.calc_face_normal(f1));
  if (!(length > 0) || n0.isZero() || n1.isZero()) return {0, 0};
  const double angle = std::atan2(n0.cross(n1).norm(), n0.dot(n1));
  const double width = (mesh.calc_face_area(f0) + mesh.calc_face_area(f1)) / length;  // (h0 + h1) / 2
  return {width > 0 ? angle / width : 0, width};
}

}  // namespace

SizingField::SizingField(const TriMesh& mesh, const SurfaceConstraints& constraints, const SizingRules& rules) {
  const SizeParams& size = rules.size;
  const double diagonal = bbox_diagonal(MeshSoupView(mesh));
  if (size.size) {
    base_ = size.size->resolved(diagonal);
  } else {
    double area = 0;
    for (const auto f : mesh.faces()) area += mesh.calc_face_area(f);
    base_ = std::sqrt(area / (kEquilateralArea * static_cast<double>(std::max<std::size_t>(1, mesh.n_faces()))));
  }
  if (size.size_max) base_ = std::min(base_, size.size_max->resolved(diagonal));
  // The floor: the user's size_min, else the chord tolerance, but never over a size the user asked
  // for a patch or region.
  const double floor =
      size.size_min ? std::min(size.size_min->resolved(diagonal), base_)
                    : std::min({rules.chord_tolerance, base_, smallest_local_size(size, diagonal)});
  const double layers = size.thickness_layers.value_or(1);
  // Only demands below the base length count.
  const auto demand = [&](const Vec3& p, double length) {
    if (length < base_) demands_.push_back({p, std::max(length, floor)});
  };
  // Demands are sampled where they hold, no farther apart than they ask (a long strip's curvature
  // holds all along it, a thin plate's thickness all across it), within a budget.
  const std::size_t most_demands = 4 * std::max<std::size_t>(rules.max_faces, mesh.n_faces());
  bool closed = true;
  for (const auto e : mesh.edges()) {
    if (mesh.is_boundary(e)) {
      closed = false;
      continue;
    }
    if (constraints.is_feature(e)) {
      // A feature edge between two corners stays whatever the remeshing does: the faces around it
      // are graded from its length, not dropped from the base length at once.
      const auto h = mesh.halfedge_handle(e, 0);
      // One shorter than the chord tolerance is below what the fidelity bound resolves (a plate's
      // thickness under the bound): the knife-edge stage may move it, and grading from it there
      // made the remeshing split the plate's walls into caps whose collapses thinned it by 12 %.
      if (rules.grade_from_corner_edges && constraints.role(mesh.from_vertex_handle(h)) == VertexRole::Fixed &&
          constraints.role(mesh.to_vertex_handle(h)) == VertexRole::Fixed &&
          mesh.calc_edge_length(e) >= rules.chord_tolerance && mesh.calc_edge_length(e) < base_) {
        demand(to_eigen(mesh.calc_edge_midpoint(e)), mesh.calc_edge_length(e));
        ++corner_edge_demands_;
      }
      continue;
    }
    const auto [curvature, width] = edge_curvature(mesh, e);
    if (!(curvature > 0)) continue;
    // Never finer than the input across the edge: below its facets' width the reference is flat
    // (and a scan's noise is no curvature to follow). The user's points per turn hold regardless:
    // a hole of 8 facets asked for 12 points gets them.
    double chord = std::max(std::sqrt(8.0 * rules.chord_tolerance / curvature), width);
    if (size.curvature_points) chord = std::min(chord, 2 * M_PI / (*size.curvature_points * curvature));
    if (chord >= base_) continue;
    const auto h = mesh.halfedge_handle(e, 0);
    const Vec3 a = to_eigen(mesh.point(mesh.from_vertex_handle(h))), b = to_eigen(mesh.point(mesh.to_vertex_handle(h)));
    const auto pieces = static_cast<std::size_t>(std::ceil((b - a).norm() / std::max(chord, floor)));
    for (std::size_t k = 0; k < pieces && demands_.size() < most_demands; ++k)
      demand(a + (b - a) * ((static_cast<double>(k) + 0.5) / static_cast<double>(pieces)), chord);
  }
  if (!size.patch_sizes.empty())
    for (const SizeDemand& d : patch_size_demands(size, soup_from_mesh(mesh), diagonal)) demand(d.point, d.length);
  for (const SizeDemand& d : rules.crossing_demands) demand(d.point, d.length);
  if (closed) {
    const double inward = signed_volume(MeshSoupView(mesh)) > 0 ? -1 : 1;
    // The reference is the input here: each face's rays skip the face itself.
    const TriangleBvh& bvh = constraints.reference_bvh();
    const bool same = bvh.surface().triangles.size() == mesh.n_faces();
    for (const auto f : mesh.faces()) {
      const Vec3 n = to_eigen(mesh.calc_face_normal(f));
      if (n.isZero()) continue;
      const auto h = mesh.halfedge_handle(f);
      const Corners corners = {to_eigen(mesh.point(mesh.from_vertex_handle(h))), to_eigen(mesh.point(mesh.to_vertex_handle(h))),
                               to_eigen(mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h))))};
      sample_thickness(bvh, corners, inward * n, same ? static_cast<std::size_t>(f.idx()) : ~std::size_t(0), floor,
                       layers, most_demands, 0);
    }
  }
  field_ = std::make_shared<SizeField>(demands_, base_, size.grading_used(), floor, region_demands(size, diagonal));
  demands_.clear();
  // Faces the field asks for: each input face's area over the equilateral triangle of the field's
  // length, the face cut into quarters until its pieces are no longer than that length (a needle
  // with one end at a fine spot asks for little beyond it).
  std::size_t evaluations = 0;
  const std::size_t most_evaluations = 4 * std::max<std::size_t>(rules.max_faces, mesh.n_faces());
  double faces = 0;
  for (const auto f : mesh.faces()) {
    const auto h = mesh.halfedge_handle(f);
    faces += faces_over(to_eigen(mesh.point(mesh.from_vertex_handle(h))), to_eigen(mesh.point(mesh.to_vertex_handle(h))),
                        to_eigen(mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h)))), evaluations, most_evaluations);
  }
  if (rules.max_faces > 0 && faces > static_cast<double>(rules.max_faces)) {
    const double scale = std::sqrt(faces / static_cast<double>(rules.max_faces));
    field_->scale(scale);
    faces /= scale * scale;
  }
  estimated_faces_ = static_cast<std::size_t>(std::lround(faces));
}

SizingField::~SizingField() = default;

void SizingField::sample_thickness(const TriangleBvh& bvh, const Corners& c, const Vec3& inward, std::size_t face,
                                   double floor, double layers, std::size_t most_demands, double parent_thickness) {
  if (demands_.size() >= most_demands) return;
  const Vec3 centroid = (c[0] + c[1] + c[2]) / 3.0;
  const TriangleBvh::RayHit hit = bvh.first_hit(centroid, inward, face);
  // Only a wall across counts (facing back within kOppositeWall): the other face of a wedge is
  // near its edge however thick the part is (example001's tangent cylinders asked for 1e-4 of the
  // diagonal, and 76,000 faces).
  if (!(hit.distance < INFINITY) ||
      unit_normal(bvh.surface(), hit.face).dot(inward) < kOppositeWall)
    return;
  const double thickness = std::max(hit.distance, floor);
  if (thickness / layers < base_) demands_.push_back({centroid, std::max(thickness / layers, floor)});
  const double longest = std::max({(c[1] - c[0]).norm(), (c[2] - c[1]).norm(), (c[0] - c[2]).norm()});
  // A plate is as thick all over; a wedge thins toward its edge, and the quarters there would be
  // cut without end (example016's letters: 175,000 samples): a piece under 3/4 of its parent's
  // thickness is not cut again.
  if (longest <= thickness / layers || thickness < kWedgeThinning * parent_thickness) return;
  const Vec3 ab = 0.5 * (c[0] + c[1]), bc = 0.5 * (c[1] + c[2]), ca = 0.5 * (c[2] + c[0]);
  for (const Corners& piece : {Corners{c[0], ab, ca}, Corners{ab, c[1], bc}, Corners{ca, bc, c[2]}, Corners{ab, bc, ca}})
    sample_thickness(bvh, piece, inward, face, floor, layers, most_demands, thickness);
}

double SizingField::faces_over(const Vec3& a, const Vec3& b, const Vec3& c, std::size_t& evaluations,
                               std::size_t most_evaluations) const {
  const double length = (*field_)((a + b + c) / 3.0);
  ++evaluations;
  const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
  if (longest <= length || evaluations >= most_evaluations)
    return 0.5 * (b - a).cross(c - a).norm() / (kEquilateralArea * length * length);
  const Vec3 ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
  return faces_over(a, ab, ca, evaluations, most_evaluations) + faces_over(ab, b, bc, evaluations, most_evaluations) +
         faces_over(ca, bc, c, evaluations, most_evaluations) + faces_over(ab, bc, ca, evaluations, most_evaluations);
}

}  // namespace meshprep::detail
