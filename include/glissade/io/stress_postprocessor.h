#pragma once

#include <deal.II/numerics/data_postprocessor.h>

#include <glissade/material/material.h>

namespace glissade
{
  /**
   * Cauchy stress and von Mises stress from the displacement gradient at the
   * output points: computed from the material law where it is plotted, so
   * the picture shows the stress of the discrete solution without a
   * projection step.
   */
  class StressPostprocessor : public DataPostprocessor<2>
  {
  public:
    explicit StressPostprocessor(const Material &material);

    void
    evaluate_vector_field(const DataPostprocessorInputs::Vector<2> &inputs,
                          std::vector<Vector<double>> &computed) const override;

    std::vector<std::string>
    get_names() const override;

    UpdateFlags
    get_needed_update_flags() const override;

  private:
    const Material &material;
  };
} // namespace glissade
