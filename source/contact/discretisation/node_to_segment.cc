#include <glissade/body/body.h>
#include <glissade/contact/discretisation/contact_discretisation.h>
#include <glissade/contact/surfaces/master_surface.h>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /**
     * The paper's discretisation: each slave node against its closest
     * point on the master surface, linearised by linearize_contact().
     */
    class NodeToSegment : public ContactDiscretisation
    {
    public:
      explicit NodeToSegment(const Context &context)
        : slave(context.slave)
        , master(context.master)
        , surface(context.surface)
      {}

      bool
      project(ContactNode &node, const bool keep_segment) const override
      {
        const Vector<double> &u  = slave.displacement();
        const Vector<double> &u0 = slave.stored_displacement();
        const Tensor<1, 2>    motion =
          node.displacement(u) - node.displacement(u0);
        const Point<2> x = node.reference_position + node.displacement(u);

        SegmentHint keep;
        if (keep_segment)
          keep = {node.segment,
                  node.s,
                  node.segment_switches >= 2,
                  node.at_vertex,
                  node.status == BiPotentialSolver::NodeStatus::stick};
        const SurfacePoint point =
          node.facing ? surface.project_facing(x, keep, node.facing_view) :
                        surface.project(x, keep);
        if (!point.valid)
          return false;
        if (keep_segment && node.segment >= 0 && point.segment != node.segment)
          ++node.segment_switches;

        node.segment   = point.segment;
        node.s         = point.s;
        node.at_vertex = point.vertex_cone > 0.;
        node.tangent   = point.tangent;
        node.normal    = point.normal;
        node.gap       = point.gap;
        const auto master_increment =
          [this](const types::global_dof_index dof) {
            return master->displacement()(dof) -
                   master->stored_displacement()(dof);
          };
        node.linearization = linearize_contact(
          x, node.shares, motion, point, master_increment, node.reaction);
        return true;
      }

    private:
      const Body          &slave;
      const Body          *master;
      const MasterSurface &surface;
    };
  } // namespace



  std::unique_ptr<ContactDiscretisation>
  create_node_to_segment(const ContactDiscretisation::Context &context)
  {
    return std::make_unique<NodeToSegment>(context);
  }
} // namespace glissade
