#include <glissade/contact/discretisation/discrete_gradient.h>

#include <cmath>
#include <vector>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /** One dof of the node's forces, counted once (a self-contact's dof may
     *  be named by both sides). */
    struct StepDof
    {
      unsigned int            body;
      types::global_dof_index dof;
      double                  motion;
      std::array<double, 2>   translation;
    };

    unsigned int
    index_of(std::vector<StepDof>         &dofs,
             const unsigned int            body,
             const types::global_dof_index dof,
             const StepMotion             &motion)
    {
      const unsigned int key = motion.one_body ? 0 : body;
      for (unsigned int k = 0; k < dofs.size(); ++k)
        if (dofs[k].body == key && dofs[k].dof == dof)
          return k;
      dofs.push_back({key,
                      dof,
                      motion.increment(body, dof),
                      motion.translation ? motion.translation(body, dof) :
                                           std::array<double, 2>{{0., 0.}}});
      return dofs.size() - 1;
    }

    /**
     * Adds to the forces of a unit normal (tangential) reaction the multiple
     * of the step's relative motion w that makes their work on the step's
     * motion the gap's change (the slip). The defect, g_n+1 - g_n - f . du,
     * is that of gaps computed to round-off of the coordinates, 1e-16 of the
     * length: divided by |w|^2 it would be noise of 1e-16 length / |w| in
     * the forces where the node barely moves (a node that sticks, a body at
     * rest). Dividing by |w|^2 + w_0^2 instead, w_0 = 1e-6 of the length,
     * keeps that noise below 1e-10 and leaves unrepaired a share w_0^2 /
     * (|w|^2 + w_0^2) of a defect that is then at most H w_0^2, 1e-12 of
     * r_n times the length: the forces stay smooth in the motion, which
     * Newton needs.
     */
    void
    correct_along_the_motion(ContactLinearization      &linearization,
                             const double               gap_change,
                             const double               slip,
                             std::vector<StepDof>      &dofs,
                             const std::vector<double> &w,
                             const double               relative_squared,
                             const StepMotion          &motion)
    {
      const double smallest_motion = 1e-6 * motion.length;
      const double denominator =
        relative_squared + smallest_motion * smallest_motion;
      const auto correct = [&](DofVector &force, const double change) {
        double work = 0.;
        for (const DofCoefficient &e : force)
          work += e.value * dofs[index_of(dofs, e.body, e.dof, motion)].motion;
        const double alpha = (change - work) / denominator;
        for (unsigned int k = 0; k < dofs.size(); ++k)
          if (w[k] != 0.)
            force.push_back({dofs[k].body, dofs[k].dof, alpha * w[k]});
      };
      correct(linearization.normal_force, gap_change);
      if (std::isfinite(slip))
        correct(linearization.tangential_force, slip);
    }
  } // namespace



  void
  make_forces_discrete_gradients(ContactLinearization &linearization,
                                 const DofVector      &start_normal_force,
                                 const double          gap_change,
                                 const double          slip,
                                 const StepMotion     &motion)
  {
    // The gradient is the gap's own (its row): node-to-segment's normal
    // force is that row, mortar's is not (its weighted gap also moves with
    // the turn of the nodal normal and the change of the mortar weights,
    // where the gap vector x - y is not along the normal), and forces
    // that are not the gap's gradient leave the linearised gap wrong by
    // as much whatever the step (a Newmark run stalled at 7e-4).
    linearization.normal_force = linearization.gap_row;
    if (!start_normal_force.empty())
      {
        for (DofCoefficient &e : linearization.normal_force)
          e.value *= 0.5;
        for (const DofCoefficient &e : start_normal_force)
          linearization.normal_force.push_back({e.body, e.dof, 0.5 * e.value});
      }
    std::vector<StepDof> dofs;
    for (const DofVector *force :
         {&linearization.normal_force, &linearization.tangential_force})
      for (const DofCoefficient &e : *force)
        index_of(dofs, e.body, e.dof, motion);

    // w: the step's motion without the bodies' common translation (its
    // projection on the vectors orthogonal to the two unit translations,
    // which are orthogonal to each other: they live on different dofs).
    std::vector<double> w(dofs.size());
    for (unsigned int k = 0; k < dofs.size(); ++k)
      w[k] = dofs[k].motion;
    for (unsigned int c = 0; c < 2; ++c)
      {
        double along = 0., norm = 0.;
        for (const StepDof &d : dofs)
          {
            along += d.translation[c] * d.motion;
            norm += d.translation[c] * d.translation[c];
          }
        if (norm > 0.)
          for (unsigned int k = 0; k < dofs.size(); ++k)
            w[k] -= along / norm * dofs[k].translation[c];
      }
    double relative_squared = 0.;
    for (unsigned int k = 0; k < dofs.size(); ++k)
      relative_squared += w[k] * dofs[k].motion;
    if (relative_squared > 0.)
      correct_along_the_motion(
        linearization, gap_change, slip, dofs, w, relative_squared, motion);
    // The rows of the linearised gap and slip are the forces too: the
    // Delassus operator W = rows K^-1 forces^T stays symmetric, as the
    // bi-potential solver needs of it (with the end's gradient as the rows
    // it took 10,000 sweeps and more in a packing of disks). They differ
    // from the gradient of the end's gap by half its change over the step
    // (H du / 2): Newton converges to the same state, at that rate.
    linearization.gap_row = linearization.normal_force;
    if (std::isfinite(slip))
      linearization.slip_row = linearization.tangential_force;
  }
} // namespace glissade
