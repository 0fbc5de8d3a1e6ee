// centreline_index.hpp (private): the closest point of the model rod's centreline Γ to each point
// of a cloud. A k-d tree (nanoflann) over the centreline's nodes gives the nearest node; the
// closest point is then searched on the intervals next to it (project_near_node: Γ between nodes
// is the cubic Hermite interpolant, optimisation/curve_distance.hpp). Built once per configuration,
// it serves every point (cloud_estimator.cpp).
#pragma once

#include <Eigen/Core>
#include <memory>

#include "rodshape/core/rod_configuration.hpp"
#include "rodshape/optimisation/curve_distance.hpp"

namespace rodshape::feedback_detail {

class CentrelineIndex {
 public:
  /// Indexes the nodes of `configuration`, which must outlive the index and have ≥ 1 node.
  explicit CentrelineIndex(const RodConfiguration& configuration);
  ~CentrelineIndex();
  CentrelineIndex(const CentrelineIndex&) = delete;
  CentrelineIndex& operator=(const CentrelineIndex&) = delete;

  /// The closest point of Γ to `point` (on the intervals next to the nearest node).
  CurveProjection project(const Eigen::Vector3d& point) const;

 private:
  struct Tree;
  const RodConfiguration& configuration_;
  std::unique_ptr<Tree> tree_;
};

}  // namespace rodshape::feedback_detail
