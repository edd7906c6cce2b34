// The broad phase of automatic contact: bounding boxes in an R-tree.

#include <deal.II/numerics/rtree.h>

#include <glissade/body/body.h>
#include <glissade/contact/step/broad_phase.h>

#include <algorithm>
#include <iterator>
#include <utility>

namespace glissade
{
  using namespace dealii;

  BroadPhase::BroadPhase(const std::vector<Side> &sides,
                         const double             alert_distance)
    : alert_distance(alert_distance)
  {
    for (const Side &side : sides)
      {
        bodies.push_back(side.body);
        chains.push_back(
          MasterChain::build_all(*side.body, side.boundary, side.entry));
      }
    boxes.resize(chains.size());
  }



  BoundingBox<2>
  BroadPhase::reach_box(const unsigned int side) const
  {
    const Vector<double> &u = bodies[side]->displacement();
    std::vector<Point<2>> all;
    double                longest_face = 0.;
    for (const MasterChain &chain : chains[side])
      {
        std::vector<Point<2>> x(chain.value_dofs.size());
        for (unsigned int k = 0; k < x.size(); ++k)
          x[k] = chain.reference_points[k] +
                 Tensor<1, 2>(
                   {u(chain.value_dofs[k][0]), u(chain.value_dofs[k][1])});
        // (segment k joins node k to node k + 1, the last to the first on
        // a closed chain)
        for (unsigned int k = 0; k < chain.faces.size(); ++k)
          longest_face =
            std::max(longest_face, x[k].distance(x[(k + 1) % x.size()]));
        all.insert(all.end(), x.begin(), x.end());
      }
    BoundingBox<2> box(all);
    box.extend(longest_face + 0.5 * alert_distance);
    return box;
  }



  std::vector<std::array<unsigned int, 2>>
  BroadPhase::couples_within_reach()
  {
    std::vector<std::pair<BoundingBox<2>, unsigned int>> leaves;
    for (unsigned int s = 0; s < chains.size(); ++s)
      {
        boxes[s] = reach_box(s);
        leaves.emplace_back(boxes[s], s);
      }
    const auto tree = pack_rtree(leaves);

    std::vector<std::array<unsigned int, 2>>             couples;
    std::vector<std::pair<BoundingBox<2>, unsigned int>> overlapping;
    for (const auto &[box, s] : leaves)
      {
        overlapping.clear();
        tree.query(boost::geometry::index::intersects(box),
                   std::back_inserter(overlapping));
        for (const auto &other : overlapping)
          if (other.second > s)
            couples.push_back({{s, other.second}});
      }
    std::sort(couples.begin(), couples.end());
    return couples;
  }
} // namespace glissade
