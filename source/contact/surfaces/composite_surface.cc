// A master boundary of several curves (include/glissade/contact/surfaces/
// composite_surface.h).

#include <glissade/contact/surfaces/composite_surface.h>

#include <algorithm>
#include <limits>

namespace glissade
{
  using namespace dealii;

  CompositeSurface::CompositeSurface(
    std::vector<std::unique_ptr<CurveSurface>> &&curves_)
    : curves(std::move(curves_))
  {
    int segments = 0, nodes = 0;
    for (const auto &curve : curves)
      {
        first_segment.push_back(segments);
        first_node.push_back(nodes);
        segments += curve->master_chain().faces.size();
        nodes += curve->master_chain().vertices.size();
      }
  }



  void
  CompositeSurface::update(const double step_start_time, const double time)
  {
    for (const auto &curve : curves)
      curve->update(step_start_time, time);
  }



  unsigned int
  CompositeSurface::curve_of_segment(const int segment) const
  {
    return std::upper_bound(first_segment.begin(),
                            first_segment.end(),
                            segment) -
           first_segment.begin() - 1;
  }



  unsigned int
  CompositeSurface::curve_of_node(const int node) const
  {
    return std::upper_bound(first_node.begin(), first_node.end(), node) -
           first_node.begin() - 1;
  }



  SurfacePoint
  CompositeSurface::numbered(SurfacePoint point, const unsigned int c) const
  {
    if (point.valid)
      point.segment += first_segment[c];
    return point;
  }



  SurfacePoint
  CompositeSurface::closest(const Point<2>                  &x,
                            const std::vector<SurfacePoint> &candidates)
  {
    SurfacePoint best;
    double       best_distance = std::numeric_limits<double>::infinity();
    for (const SurfacePoint &point : candidates)
      if (point.valid && x.distance(point.point) < best_distance)
        {
          best          = point;
          best_distance = x.distance(point.point);
        }
    return best;
  }



  SurfacePoint
  CompositeSurface::project(const Point<2> &x, const SegmentHint &keep) const
  {
    // A kept segment is kept on its own curve; the other curves are
    // searched afresh, and the closest point of all wins.
    const int kept_on =
      keep.segment >= 0 ? int(curve_of_segment(keep.segment)) : -1;
    std::vector<SurfacePoint> candidates;
    for (unsigned int c = 0; c < curves.size(); ++c)
      {
        SegmentHint hint;
        if (int(c) == kept_on)
          {
            hint = keep;
            hint.segment -= first_segment[c];
          }
        candidates.push_back(numbered(curves[c]->project(x, hint), c));
      }
    return closest(x, candidates);
  }



  SurfacePoint
  CompositeSurface::project_facing(const Point<2>    &x,
                                   const SegmentHint &keep,
                                   const FacingView  &view) const
  {
    const int own_curve =
      view.master_node >= 0 ? int(curve_of_node(view.master_node)) : -1;
    const int kept_on =
      keep.segment >= 0 ? int(curve_of_segment(keep.segment)) : -1;
    std::vector<SurfacePoint> candidates;
    for (unsigned int c = 0; c < curves.size(); ++c)
      {
        // (a node's own curve with its place on it; the curves before it
        // hold the node's curve with their own nodes)
        if (int(c) < own_curve)
          continue;
        FacingView local = view;
        local.master_node =
          int(c) == own_curve ? view.master_node - first_node[c] : -1;
        SegmentHint hint;
        if (int(c) == kept_on)
          {
            hint = keep;
            hint.segment -= first_segment[c];
          }
        candidates.push_back(
          numbered(curves[c]->project_facing(x, hint, local), c));
      }
    return closest(x, candidates);
  }



  std::vector<unsigned int>
  CompositeSurface::vertices() const
  {
    std::vector<unsigned int> all;
    for (const auto &curve : curves)
      {
        const auto &chain = curve->master_chain().vertices;
        all.insert(all.end(), chain.begin(), chain.end());
      }
    return all;
  }



  std::vector<types::global_dof_index>
  CompositeSurface::dofs() const
  {
    std::vector<types::global_dof_index> all;
    for (const auto &curve : curves)
      {
        const auto dofs = curve->dofs();
        all.insert(all.end(), dofs.begin(), dofs.end());
      }
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    return all;
  }
} // namespace glissade
