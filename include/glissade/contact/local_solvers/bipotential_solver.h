#pragma once

#include <glissade/lac/compliance_matrix.h>

#include <array>
#include <string>
#include <vector>

namespace glissade
{
  /**
   * The local contact problem of the bi-potential method (de Saxce and Feng
   * 1998; Feng et al. 2005), step 4 of CONTACT_ALGORITHM.md: given the
   * condensed system
   *
   *   u_k = u_k^free + sum_l W_kl r_l,     k = 0 .. n-1,
   *
   * find the reactions r_k = (r_t, r_n) on the n active slave nodes that
   * satisfy Signorini's condition and Coulomb's law at every node.
   *
   * <h3>Sign conventions</h3>
   * Everything is expressed in the node's local frame (t, n), component 0
   * tangential and 1 normal, n pointing out of the master body.
   * - r_k is the force that the master exerts on the slave node. r_n >= 0:
   *   contact can only push the slave away from the master (no adhesion).
   * - u_k = (u_t, g): u_t is the tangential slip of the slave relative to
   *   the master accumulated since the start of the load increment, g the
   *   normal gap, positive when the node is outside the master body. The
   *   free values u_k^free are those of the contact-free predictor.
   * - W is a compliance: a positive r_n opens the gap, so W_kk[n][n] > 0
   *   for every node with at least one deformable body.
   * - Coulomb: |r_t| <= mu r_n; if the node slips (u_t != 0) then
   *   r_t = -mu r_n u_t / |u_t|: friction on the slave opposes the slave's
   *   slip relative to the master.
   *
   * <h3>The iteration</h3>
   * With the modified displacement u~ = (u_t, g + mu |u_t|), de Saxce's
   * bi-potential turns the whole law (Signorini + Coulomb) into one
   * inclusion, -u~ in N_K(r) (the normal cone of the Coulomb cone
   * K = {|r_t| <= mu r_n} at r), equivalently the fixed point
   *
   *   r = proj_K( r - rho u~ )        for any rho > 0.
   *
   * The solver sweeps the nodes in order and replaces r_k by the right-hand
   * side, computed with the latest reactions of all other nodes (nonlinear
   * Gauss-Seidel), with rho_k = beta / W_kk[n][n], 0 < beta < 2.
   *
   * Why this converges without friction: with mu = 0 the update reduces to
   * r_n <- max(0, r_n - (beta / W_kk) g_k), which is exactly projected SOR
   * (Cryer 1971) with relaxation factor beta on the linear complementarity
   * problem  g = g^free + W_nn r_n >= 0, r_n >= 0, g . r_n = 0. For a
   * symmetric positive (semi-)definite W_nn, projected SOR is a descent
   * method on the energy 1/2 r.W r + r.g^free restricted to r >= 0, and
   * each node update decreases it strictly unless r_k is already optimal,
   * provided 0 < beta < 2 (a one-dimensional quadratic step of length beta
   * times the exact minimiser stays in the descent region exactly for beta in
   * (0, 2)). Every limit point is therefore a solution; the gaps are unique
   * even when W is only semi-definite. With friction the law is not
   * associated and no such energy exists; the iteration is then a fixed
   * point scheme that converges in practice for moderate mu, and the solver
   * reports it when it does not (Outcome::max_sweeps_reached or diverged).
   *
   * <h3>Implementation notes</h3>
   * - The displacements u are kept up to date incrementally: when r_l
   *   changes by delta, u += W_{.l} delta (one block column). A node whose
   *   reaction does not change (an open node staying open) costs O(1), so an
   *   all-open problem is one cheap sweep. u is recomputed from scratch
   *   whenever convergence is tested and every 128 sweeps, so round-off
   *   cannot accumulate.
   * - A sweep costs O(n m) where m is the number of nodes whose reaction
   *   changes, i.e. O(n^2) for a dense W and a large contact zone.
   * - Convergence requires both (a) the largest change of a reaction over
   *   one sweep to be below change_tolerance * max(max_k |r_k|,
   *   reaction_floor), and (b) the residuals of compute_contact_residuals()
   *   to be below residual_tolerance * L, where L is the larger of
   *   max_k |u_k^free|, s max_k |r_k| and length_floor (s: the force-to-length
   *   scale). (a) alone can be fooled by a slowly converging iteration, (b)
   *   is the actual statement of the contact law.
   * - The input is validated before anything is changed: sizes, finite
   *   values, mu >= 0, 0 < beta < 2 and W_kk[n][n] > 0. A node with
   *   W_kk[n][n] = 0 (both bodies rigid) has a gap that no reaction can
   *   change: it is listed in Result::singular_nodes and nothing is solved.
   * - If the iteration blows up (non-finite values, or reactions 1e30 times
   *   larger than the problem's force scale) r is restored to its input
   *   value and Outcome::diverged is returned. No NaN ever leaves solve().
   */
  class BiPotentialSolver
  {
  public:
    using Vector2 = ComplianceMatrix::Vector2;

    /**
     * How rho_k is derived from the diagonal block W_kk.
     */
    enum class RhoChoice
    {
      /**
       * rho_k = beta / W_kk[n][n] (CONTACT_ALGORITHM.md, step 4). For
       * a node in stick, the tangential update is r_t <- r_t - rho_k u_t,
       * which contracts only if rho_k W_kk[t][t] < 2, i.e.
       * W_kk[t][t] < (2 / beta) W_kk[n][n].
       */
      normal_compliance,
      /**
       * rho_k = beta / lambda_max(W_kk) for nodes with mu > 0, and
       * beta / W_kk[n][n] for frictionless nodes. Safe when the tangential
       * compliance exceeds the normal one (e.g. a thin body loaded in
       * bending), at the price of smaller normal steps.
       */
      largest_diagonal_compliance
    };

    struct Settings
    {
      /** Relaxation factor, 0 < beta < 2. */
      double beta = 1.;

      RhoChoice rho_choice = RhoChoice::normal_compliance;

      /** Hard limit on the number of Gauss-Seidel sweeps. */
      unsigned int max_sweeps = 10000;

      /** Relative tolerance on the change of r over one sweep. */
      double change_tolerance = 1e-10;

      /** Force: floor of the denominator of the change test. */
      double reaction_floor = 0.;

      /** Relative tolerance on the residuals (see the class comment). */
      double residual_tolerance = 1e-10;

      /** Length: floor of the reference length of the residual test. */
      double length_floor = 0.;

      /**
       * Length per unit force s used in the complementarity residual
       * |min(g, s r_n)| and the friction residual. Zero or negative: use
       * max_k W_kk[n][n].
       */
      double force_to_length_scale = 0.;
      /**
       * The polish: fix the statuses of the iterate and solve the then
       * linear contact law exactly on the closed nodes (a LAPACK LU of
       * their W block); the answer is kept only if it satisfies the law's
       * residual test. It is tried once the statuses have not changed for
       * 5 sweeps (then 20, 80, ... while they stay unchanged), every this
       * many sweeps without convergence, and at the last sweep. 0: never.
       */
      unsigned int polish_period = 25;
    };

    enum class NodeStatus
    {
      /** r = 0: no contact (g >= 0). */
      open,
      /** r_n > 0, |r_t| < mu r_n: no slip (u = 0). */
      stick,
      /**
       * r_n > 0, |r_t| = mu r_n: slip opposed by friction (g = 0). A closed
       * frictionless node is reported as slipping (free sliding).
       */
      slip
    };

    enum class Outcome
    {
      converged,
      max_sweeps_reached,
      diverged,
      /** Sizes, NaN/Inf, mu < 0 or beta outside (0, 2): r untouched. */
      invalid_input,
      /** Some W_kk[n][n] <= 0: listed in singular_nodes, r untouched. */
      singular_node
    };

    /**
     * Residuals of the contact law, all in length units (see
     * compute_contact_residuals()). Each is a maximum over the nodes.
     */
    struct Residuals
    {
      /** max_k |min(g_k, s r_n,k)|: Signorini's condition. */
      double complementarity = 0.;
      /**
       * max_k |s r_t - proj_[-mu s r_n, mu s r_n](s r_t - u_t)|: zero iff
       * |r_t| <= mu r_n and either u_t = 0 or r_t = -mu r_n u_t/|u_t|.
       */
      double friction = 0.;
      /** max_k max(0, -g_k). */
      double max_penetration = 0.;
      /** max_k s max(0, |r_t| - mu r_n). */
      double max_cone_violation = 0.;
    };

    struct Result
    {
      Outcome outcome   = Outcome::invalid_input;
      bool    converged = false;

      /** Gauss-Seidel sweeps done (1 for a problem solved by its start). */
      unsigned int sweeps = 0;
      /** Whether the answer came from the active-set polish. */
      bool polished = false;

      /** Largest change of a node's reaction |delta r_k| in the last sweep. */
      double last_reaction_change = 0.;
      /** The bound that last_reaction_change had to meet (force). */
      double reaction_change_bound = 0.;
      /** The bound that the residuals had to meet (length). */
      double residual_bound = 0.;
      /** The force-to-length scale s actually used. */
      double force_to_length_scale = 0.;

      /** Residuals of the returned reactions. */
      Residuals residuals;

      /** u_k = u_k^free + sum_l W_kl r_l for the returned r. */
      std::vector<Vector2>    displacement;
      std::vector<NodeStatus> status;

      /** Nodes with W_kk[n][n] <= 0 (Outcome::singular_node). */
      std::vector<unsigned int> singular_nodes;

      /** A sentence for the log; says what is wrong unless converged. */
      std::string message;
    };

    /** A solver with the default Settings. */
    BiPotentialSolver();

    explicit BiPotentialSolver(const Settings &settings);

    const Settings &
    get_settings() const;

    /**
     * Solve for the reactions. r is the starting guess on input (e.g. the
     * reactions of the previous Newton iteration; an empty vector means
     * zero) and the solution on output. mu[k] >= 0 is the friction
     * coefficient of node k (0: frictionless). u_free[k] = (u_t^free,
     * g^free).
     */
    Result
    solve(const ComplianceMatrix     &W,
          const std::vector<Vector2> &u_free,
          const std::vector<double>  &mu,
          std::vector<Vector2>       &r) const;

    /**
     * The same with each node's normal reaction capped, r_n <= cap[k] (a
     * layer that yields, as an abradable coating: at the cap the node may
     * go behind the master, g <= 0; infinity: no cap). The law is then
     * the projection on the Coulomb cone truncated by the cap
     * (project_on_capped_cone()), a box-constrained LCP without friction:
     * Gauss-Seidel converges as before; the polish is not tried while a
     * node is at its cap.
     */
    Result
    solve(const ComplianceMatrix     &W,
          const std::vector<Vector2> &u_free,
          const std::vector<double>  &mu,
          std::vector<Vector2>       &r,
          const std::vector<double>  &cap) const;

    /**
     * The same law by a primal-dual active-set iteration (a semismooth
     * Newton method on the law): the statuses (open, stick, slip and its
     * direction) of r on input, then, repeatedly, the reactions of those
     * statuses (solve_for_statuses()) and the statuses they imply, from
     * x_k = r_k - rho_k (u_t, g + mu |u_t|) with rho_k = 1 / |W_kk[n][n]|,
     * until they repeat and the law holds to the tolerance of the
     * settings. Unlike Gauss-Seidel it needs no positive semi-definite W:
     * it is what solves the local problem of a Newton step whose tangent is
     * indefinite (a body past a limit point held by its contact), from
     * the statuses of the previous iteration. Outcome::max_sweeps_reached
     * (here: status updates) if the statuses cycle.
     */
    Result
    solve_by_active_set(const ComplianceMatrix     &W,
                        const std::vector<Vector2> &u_free,
                        const std::vector<double>  &mu,
                        std::vector<Vector2>       &r) const;

    /**
     * The reactions for given statuses: open, r = 0; closed (frictionless
     * or slipping), g = 0; stick, u = 0; slipping, r_t = slip_sign mu r_n.
     * A dense linear system in the closed nodes' reactions (LAPACK's LU);
     * false if nothing is closed or it is singular.
     */
    static bool
    solve_for_statuses(const ComplianceMatrix        &W,
                       const std::vector<Vector2>    &u_free,
                       const std::vector<double>     &mu,
                       const std::vector<NodeStatus> &status,
                       const std::vector<double>     &slip_sign,
                       std::vector<Vector2>          &r);

    /**
     * The projection onto K_mu = {|r_t| <= mu r_n} in the (r_t, r_n) plane:
     * x itself inside K_mu, 0 in the polar cone {x_n <= -mu |x_t|}, else the
     * closest point on the edge r_t = sign(x_t) mu r_n.
     */
    static Vector2
    project_on_coulomb_cone(const Vector2 &x, double mu);

    /** The projection onto K_mu truncated by r_n <= cap. */
    static Vector2
    project_on_capped_cone(const Vector2 &x, double mu, double cap);

    /** The status that the contact law assigns to a solved node. */
    static NodeStatus
    classify(const Vector2 &r, double mu);

  private:
    Settings settings;
  };

  /**
   * The residuals of the contact law for given reactions, computed from
   * scratch (u = u_free + W r), independently of any iteration. s is the
   * force-to-length scale (<= 0: max_k W_kk[n][n]). If displacement is not
   * null it receives u.
   */
  BiPotentialSolver::Residuals
  compute_contact_residuals(
    const ComplianceMatrix                        &W,
    const std::vector<BiPotentialSolver::Vector2> &u_free,
    const std::vector<double>                     &mu,
    const std::vector<BiPotentialSolver::Vector2> &r,
    double                                         force_to_length_scale,
    std::vector<BiPotentialSolver::Vector2>       *displacement = nullptr,
    const std::vector<double>                     &cap          = {});
} // namespace glissade
