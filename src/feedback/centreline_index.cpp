// centreline_index.cpp: the nearest node by a nanoflann k-d tree, then the closest point on the
// intervals next to it (centreline_index.hpp).
#include "centreline_index.hpp"

#include <cstddef>
#include <nanoflann.hpp>

namespace rodshape::feedback_detail {

/// The k-d tree over the nodes. Its types are its own members rather than a file's anonymous
/// namespace: Tree has external linkage, and a field of an anonymous type in it is GCC's
/// -Wsubobject-linkage wherever this file is not the main one (a unity batch).
struct CentrelineIndex::Tree {
  /// nanoflann's view of the nodes p_i.
  struct NodeCloud {
    const RodConfiguration& c;
    std::size_t kdtree_get_point_count() const { return c.p.size(); }
    double kdtree_get_pt(std::size_t i, std::size_t dim) const {
      return c.p[i](static_cast<Eigen::Index>(dim));
    }
    template <class BoundingBox>
    bool kdtree_get_bbox(BoundingBox& /*box*/) const {
      return false;  // let nanoflann compute it
    }
  };
  using NodeTree =
      nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, NodeCloud>,
                                          NodeCloud,
                                          3,
                                          std::size_t>;

  explicit Tree(const RodConfiguration& c)
      : nodes{c}, index(3, nodes, nanoflann::KDTreeSingleIndexAdaptorParams(8)) {
    index.buildIndex();
  }
  NodeCloud nodes;
  NodeTree index;
};

CentrelineIndex::CentrelineIndex(const RodConfiguration& configuration)
    : configuration_(configuration), tree_(std::make_unique<Tree>(configuration)) {}

CentrelineIndex::~CentrelineIndex() = default;

CurveProjection CentrelineIndex::project(const Eigen::Vector3d& point) const {
  std::size_t nearest = 0;
  double squared = 0.0;
  nanoflann::KNNResultSet<double, std::size_t> result(1);
  result.init(&nearest, &squared);
  tree_->index.findNeighbors(result, point.data(), nanoflann::SearchParams());
  return project_near_node(configuration_, point, static_cast<int>(nearest));
}

}  // namespace rodshape::feedback_detail
