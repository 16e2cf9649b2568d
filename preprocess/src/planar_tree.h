#pragma once
// nanoflann's k-d tree over points of a plane (the reconstruction's reference plane).

#include <Eigen/Core>
#include <nanoflann.hpp>

#include <cstddef>
#include <vector>

namespace meshprep::detail {

/// nanoflann's dataset interface over 2D points (the vector must outlive the tree).
struct PlanarPoints {
  const std::vector<Eigen::Vector2d>* points;
  std::size_t kdtree_get_point_count() const { return points->size(); }
  double kdtree_get_pt(std::size_t i, std::size_t dim) const { return (*points)[i][static_cast<Eigen::Index>(dim)]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

using PlanarTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PlanarPoints>, PlanarPoints, 2>;

}  // namespace meshprep::detail
