#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <glissade/description/kinematics.h>
#include <glissade/description/plane_hypothesis.h>
#include <glissade/material/hyperelastic_law.h>
#include <glissade/material/hypothesis.h>

#include <any>
#include <memory>
#include <string>
#include <vector>

namespace glissade
{
  /** What the 2D solver needs at one quadrature point. */
  struct MaterialPointResponse
  {
    /** In-plane second Piola-Kirchhoff stress. */
    dealii::SymmetricTensor<2, 2> stress;
    /** dS/dE restricted to the plane (statically condensed in plane stress). */
    dealii::SymmetricTensor<4, 2> tangent;
    /** Out-of-plane stretch: 1 in plane strain, solved for in plane stress. */
    double out_of_plane_stretch = 1.;
    /**
     * Axisymmetric: the hoop stress S_33, its coupling dS_ab/dE_33 =
     * dS_33/dE_ab (the law's D_ab33) and dS_33/dE_33 (zero otherwise:
     * the assembly adds the hoop terms only for an axisymmetric body).
     */
    double                        hoop_stress = 0.;
    dealii::SymmetricTensor<2, 2> hoop_coupling;
    double                        hoop_stiffness = 0.;
  };

  /**
   * The material of one body: a 3D hyperelastic law reduced to the plane.
   * It takes the displacement gradient H = F - I (not F) so that the strain
   * is formed without cancellation (see HyperelasticLaw).
   *
   * Plane strain fixes E_33 = 0. Plane stress solves S_33(E_33) = 0 by a
   * local Newton iteration and condenses the tangent,
   *   D_ab_cd - D_ab_33 D_33_cd / D_33_33,
   * which is exact for any law (for Saint Venant-Kirchhoff it gives the
   * textbook plane-stress constants). Axisymmetric: the hoop stretch is
   * kinematic, F_33 = 1 + u_r / r, so E_33 = u_r / r + (u_r / r)^2 / 2 is
   * given and S_33 with its tangent terms returned beside the in-plane
   * ones.
   *
   * Small strain (Kinematics): the strain is epsilon = sym(H) (E_33 = u_r
   * / r, axisymmetric) and the stress D_0 : epsilon, D_0 the law's tangent
   * at rest; the same hypotheses reduce it to the plane, and the Cauchy
   * stress is that stress (no push-forward).
   */
  class Material
  {
  public:
    Material(std::unique_ptr<HyperelasticLaw> law,
             const PlaneHypothesis            hypothesis,
             const Kinematics kinematics = Kinematics::large_strain);

    /**
     * The law by name (LawRegistry) with the Lame constants of E and nu,
     * and the law's own settings (what its parse_parameters returned).
     */
    static Material
    create(const std::string    &law_name,
           const double          young_modulus,
           const double          poisson_ratio,
           const PlaneHypothesis hypothesis,
           const Kinematics      kinematics   = Kinematics::large_strain,
           const std::any       &law_settings = {});

    /**
     * `hoop_strain_ratio` is u_r / r at the point (axisymmetric bodies
     * only; ignored otherwise).
     */
    MaterialPointResponse
    evaluate(const dealii::Tensor<2, 2> &displacement_gradient,
             const double                hoop_strain_ratio = 0.) const;

    /** The stored energy per unit reference volume at the point. */
    double
    energy(const dealii::Tensor<2, 2> &displacement_gradient,
           const double                hoop_strain_ratio = 0.) const;

    /**
     * Cauchy stress in 3D (sigma_33 is non-zero in plane strain; the hoop
     * stress of an axisymmetric body).
     */
    dealii::SymmetricTensor<2, 3>
    cauchy_stress(const dealii::Tensor<2, 2> &displacement_gradient,
                  const double                hoop_strain_ratio = 0.) const;

    bool
    small_strain() const
    {
      return kinematics == Kinematics::small_strain;
    }

    std::string
    law_name() const
    {
      return law->name();
    }

  private:
    /** The 3D strain for an in-plane H and a given E_33: Green-Lagrange's,
     *  or sym(H) at small strain. */
    dealii::SymmetricTensor<2, 3>
    strain(const dealii::Tensor<2, 2> &H, const double e33) const;

    /** E_33 of the hoop strain ratio u_r / r (axisymmetric). */
    double
    hoop_strain(const double hoop_strain_ratio) const;

    /** S and D = dS/dE at the strain E: the law's, or D_0 : E and D_0. */
    void
    stress(const dealii::SymmetricTensor<2, 3> &E,
           dealii::SymmetricTensor<2, 3>       &S,
           dealii::SymmetricTensor<4, 3>       &D) const;

    /** Solves S_33 = 0 for E_33 (plane stress); returns E_33. */
    double
    solve_out_of_plane(const dealii::Tensor<2, 2>    &H,
                       dealii::SymmetricTensor<2, 3> &S,
                       dealii::SymmetricTensor<4, 3> &D) const;

    using ThirdDirection = Hypothesis::ThirdDirection;
    std::shared_ptr<const HyperelasticLaw> law;
    /** What the hypothesis makes of E_33 (Hypothesis). */
    ThirdDirection third;
    Kinematics     kinematics;
    /** The law's tangent at rest (small strain). */
    dealii::SymmetricTensor<4, 3> tangent_at_rest;
  };
} // namespace glissade
