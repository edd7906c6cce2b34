#pragma once

#include <deal.II/numerics/data_postprocessor.h>

#include <glissade/material/body_materials.h>

namespace glissade
{
  /**
   * Cauchy stress and von Mises stress from the displacement gradient at the
   * output points: computed from the material law where it is plotted, so
   * the picture shows the stress of the discrete solution without a
   * projection step.
   *
   * For Hermite elements (3 components per displacement component) the
   * gradient is read from the derivative dofs, interpolated bilinearly
   * between the nodes where it is exact.
   *
   * For an axisymmetric body sigma_zz is the hoop stress, with the hoop
   * strain u_r / r (its limit du_r / dr on the axis).
   */
  class StressPostprocessor : public dealii::DataPostprocessor<2>
  {
  public:
    StressPostprocessor(const BodyMaterials &materials,
                        const unsigned int   components_per_displacement,
                        const bool           strains_the_hoop = false);

    void
    evaluate_vector_field(
      const dealii::DataPostprocessorInputs::Vector<2> &inputs,
      std::vector<dealii::Vector<double>> &computed) const override;

    std::vector<std::string>
    get_names() const override;

    dealii::UpdateFlags
    get_needed_update_flags() const override;

  private:
    const BodyMaterials &materials;
    const unsigned int   per_dim;
    /** Hypothesis::strains_the_hoop() of the body. */
    const bool strains_the_hoop;
  };
} // namespace glissade
