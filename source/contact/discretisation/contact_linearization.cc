#include <glissade/contact/discretisation/contact_linearization.h>

#include <cmath>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /** One entry of the map U -> x - c(s): (body, dof, component, w, dw/ds). */
    struct Entry
    {
      unsigned int            body;
      types::global_dof_index dof;
      unsigned int            component;
      double                  weight;
      double                  derivative;
    };

    /** The slave point's shares (a node: weight 1), the master dofs with
     *  -phi. */
    std::vector<Entry>
    relative_map(const SlaveShares                &slave,
                 const std::vector<SurfaceWeight> &master)
    {
      std::vector<Entry> map;
      map.reserve(2 * slave.size() + master.size());
      for (const SlaveShare &share : slave)
        for (unsigned int c = 0; c < 2; ++c)
          map.push_back({0, share.dofs[c], c, share.weight, 0.});
      for (const auto &w : master)
        map.push_back({1, w.dof, w.component, -w.value, -w.derivative});
      return map;
    }
  } // namespace



  ContactLinearization
  linearize_contact(
    const Point<2>                                       &x,
    const SlaveShares                                    &slave_shares,
    const Tensor<1, 2>                                   &slave_motion,
    const SurfacePoint                                   &point,
    const std::function<double(types::global_dof_index)> &master_increment,
    const std::array<double, 2>                          &reaction)
  {
    ContactLinearization result;
    const Tensor<1, 2>  &t     = point.tangent;
    const Tensor<1, 2>  &n     = point.normal;
    const Tensor<1, 2>  &dc    = point.first_derivative;
    const Tensor<1, 2>   r     = x - point.point;
    const double         speed = dc.norm();

    const std::vector<Entry> kinematics =
      relative_map(slave_shares, point.kinematics);
    const std::vector<Entry> forces = relative_map(slave_shares, point.forces);

    // The relative motion since the increment began, d, and its
    // derivative along the curve, d' (the master point is a material one).
    // At a vertex with a cone the node is held at the vertex itself, so d
    // is its offset from the vertex, x - c, whatever the node did earlier
    // in the increment (it may have slid there along a facet).
    Tensor<1, 2> d, d_prime;
    if (point.vertex_cone > 0.)
      d = r;
    else
      {
        d       = slave_motion - point.motion_since_step_start;
        d_prime = -point.motion_derivative;
        for (const auto &e : kinematics)
          if (e.body == 1)
            {
              const double du = master_increment(e.dof);
              d[e.component] += e.weight * du;
              d_prime[e.component] += e.derivative * du;
            }
      }
    result.gap         = point.gap;
    result.slip        = t * d;
    result.vertex_cone = point.vertex_cone;

    // ds/dU from the projection (c - x) . c' = 0: on a curve,
    //   ds = [c' . delta(x - c)|_s - (x - c) . delta c'|_s] / D,
    //   D  = c' . c' - (x - c) . c'' (the curvature term),
    // and d theta/dU from the turn of c' = delta c'|_s + c'' ds. At a
    // corner node the point does not slide and the surface gives theta.
    const double D = dc * dc - r * point.second_derivative;
    DofVector    sliding_row, rotation_row;
    const bool   slides =
      !point.on_vertex && std::abs(D) > 1e-12 * (dc * dc) && speed > 0.;
    const double n_ddc = n * point.second_derivative;
    for (const auto &e : kinematics)
      {
        const double ds =
          slides ?
            (e.weight * dc[e.component] - e.derivative * r[e.component]) / D :
            0.;
        const double dtheta =
          slides ? (-e.derivative * n[e.component] + n_ddc * ds) / speed : 0.;
        if (ds != 0.)
          sliding_row.push_back({e.body, e.dof, ds});
        if (dtheta != 0.)
          rotation_row.push_back({e.body, e.dof, dtheta});
      }
    if (point.on_vertex)
      for (const auto &w : point.vertex_rotation)
        rotation_row.push_back({1, w.dof, w.value});

    // dg = n . (delta(x - c)|_s - c' ds) + (x - c) . delta n, and
    // du_t = t . (delta(x - c)|_s + d' ds) + d . delta t, with
    // delta n = -theta t and delta t = theta n. On a smooth curve n . c' = 0
    // and (x - c) . t = 0; at a corner node (x - c) . t need not vanish.
    for (const auto &e : kinematics)
      {
        result.gap_row.push_back({e.body, e.dof, e.weight * n[e.component]});
        result.slip_row.push_back({e.body, e.dof, e.weight * t[e.component]});
      }
    const double n_dc = n * dc, r_t = r * t, d_t = d_prime * t, d_n = d * n;
    for (const auto &e : sliding_row)
      {
        if (n_dc != 0.)
          result.gap_row.push_back({e.body, e.dof, -n_dc * e.value});
        result.slip_row.push_back({e.body, e.dof, d_t * e.value});
      }
    for (const auto &e : rotation_row)
      {
        if (r_t != 0.)
          result.gap_row.push_back({e.body, e.dof, -r_t * e.value});
        result.slip_row.push_back({e.body, e.dof, d_n * e.value});
      }

    // The forces F_e = v_e lambda_c(e) of the reaction, and their
    // derivative at fixed r: dF_e = v_e' lambda ds + v_e mu d theta, with
    // lambda = r_t t + r_n n and mu = r_t n - r_n t (d lambda = theta mu).
    const Tensor<1, 2> lambda = reaction[0] * t + reaction[1] * n;
    const Tensor<1, 2> mu     = reaction[0] * n - reaction[1] * t;
    DofVector          sliding_load, rotation_load;
    for (const auto &e : forces)
      {
        result.tangential_force.push_back(
          {e.body, e.dof, e.weight * t[e.component]});
        result.normal_force.push_back(
          {e.body, e.dof, e.weight * n[e.component]});
        if (e.derivative != 0. && !sliding_row.empty())
          sliding_load.push_back(
            {e.body, e.dof, e.derivative * lambda[e.component]});
        if (!rotation_row.empty())
          rotation_load.push_back({e.body, e.dof, e.weight * mu[e.component]});
      }
    if (!sliding_load.empty())
      result.tangent_terms.push_back({sliding_load, sliding_row});
    if (!rotation_load.empty())
      result.tangent_terms.push_back({rotation_load, rotation_row});
    return result;
  }
} // namespace glissade
