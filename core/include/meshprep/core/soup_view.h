#pragma once
/// \file soup_view.h
/// A non-owning view of a triangle surface (a span of points and a span of triangles), what the
/// quality module's measuring functions read, as meshoptimizer's analysers read raw buffers: a
/// TriangleSoup converts to it implicitly, and MeshSoupView adapts a halfedge mesh to it without
/// copying the mesh's points. The view never outlives what it looks at.

#include "meshprep/core/mesh.h"

#include <cstddef>
#include <vector>

namespace meshprep {

/// A contiguous array seen, not owned (std::span is C++20).
template <class T>
class Span {
 public:
  Span() = default;
  Span(const T* data, std::size_t size) : data_(data), size_(size) {}
  Span(const std::vector<T>& v) : data_(v.data()), size_(v.size()) {}  // NOLINT: implicit by design

  const T& operator[](std::size_t i) const { return data_[i]; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }
  const T& front() const { return data_[0]; }
  const T* data() const { return data_; }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }

 private:
  const T* data_ = nullptr;
  std::size_t size_ = 0;
};

/// The points of a surface, seen in either of the two layouts meshprep holds them in: Eigen
/// vectors (TriangleSoup) or OpenMesh vectors (TriMesh::points()). The two are unrelated types,
/// so neither is read through the other (no reinterpret_cast): operator[] copies the three
/// coordinates of the one it has into a Vec3, exactly (the same doubles, so the same results).
class PointSpan {
 public:
  PointSpan() = default;
  PointSpan(const std::vector<Vec3>& points) : eigen_(points.data()), size_(points.size()) {}  // NOLINT: implicit
  PointSpan(const Vec3* points, std::size_t size) : eigen_(points), size_(size) {}
  PointSpan(const OpenMesh::Vec3d* points, std::size_t size) : openmesh_(points), size_(size) {}

  Vec3 operator[](std::size_t i) const { return eigen_ ? eigen_[i] : to_eigen(openmesh_[i]); }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }

 private:
  const Vec3* eigen_ = nullptr;
  const OpenMesh::Vec3d* openmesh_ = nullptr;
  std::size_t size_ = 0;
};

/// Indexed triangles seen, not owned. Invariant (as TriangleSoup's): every index is < points.size().
struct SoupView {
  PointSpan points;
  Span<Triangle> triangles;

  SoupView() = default;
  SoupView(PointSpan p, Span<Triangle> t) : points(p), triangles(t) {}
  /// Views a soup (implicit, so that every measuring function still takes a TriangleSoup).
  SoupView(const TriangleSoup& soup) : points(soup.points), triangles(soup.triangles) {}  // NOLINT: implicit
};

/// A halfedge mesh seen as the soup soup_from_mesh(mesh) would make: the same faces in the same
/// order (deleted ones skipped), the same corners, the same vertex numbering. Unlike the soup it
/// borrows the mesh's points (TriMesh::points(), one contiguous array) when no vertex is deleted;
/// it owns the triangle indices (3 per face: the halfedge mesh has no index array), and, if
/// vertices are deleted but not yet garbage-collected, a compacted copy of the points.
/// It sees the mesh as it is when made: it must be made again after the mesh's connectivity
/// changes, and must not outlive the mesh; moved points are seen (when borrowed).
class MeshSoupView {
 public:
  explicit MeshSoupView(const TriMesh& mesh);
  MeshSoupView(const MeshSoupView&) = delete;  // the view would point into the other's arrays
  MeshSoupView& operator=(const MeshSoupView&) = delete;

  operator SoupView() const { return view(); }  // NOLINT: implicit, as a soup's
  SoupView view() const { return {points_, triangles_}; }
  const std::vector<Triangle>& triangles() const { return triangles_; }

 private:
  std::vector<Vec3> compacted_;  ///< only when the mesh has deleted vertices
  std::vector<Triangle> triangles_;
  PointSpan points_;
};

}  // namespace meshprep
