#include <glissade/io/stress_postprocessor.h>

#include <cmath>

namespace glissade
{
  using namespace dealii;

  StressPostprocessor::StressPostprocessor(
    const BodyMaterials &materials,
    const unsigned int   components_per_displacement,
    const bool           strains_the_hoop)
    : materials(materials)
    , per_dim(components_per_displacement)
    , strains_the_hoop(strains_the_hoop)
  {}



  std::vector<std::string>
  StressPostprocessor::get_names() const
  {
    return {"sigma_xx", "sigma_yy", "sigma_xy", "sigma_zz", "von_Mises"};
  }



  UpdateFlags
  StressPostprocessor::get_needed_update_flags() const
  {
    if (strains_the_hoop)
      return update_values | update_gradients | update_quadrature_points;
    return per_dim == 1 ? update_gradients : update_values;
  }



  void
  StressPostprocessor::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<2> &inputs,
    std::vector<Vector<double>>              &computed) const
  {
    const Material &material =
      materials.of_cell(inputs.template get_cell<2>()->material_id());
    for (unsigned int p = 0; p < computed.size(); ++p)
      {
        Tensor<2, 2> H;
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = 0; j < 2; ++j)
            H[i][j] = per_dim == 1 ?
                        inputs.solution_gradients[p][i][j] :
                        inputs.solution_values[p][i * per_dim + 1 + j];
        if (!(determinant(unit_symmetric_tensor<2>() + H) > 0.))
          {
            // Inverted material: nothing meaningful to plot, and NaN must
            // never reach an output file.
            computed[p] = 0.;
            continue;
          }
        // (u_r / r, and its limit du_r / dr on the axis)
        double hoop = 0.;
        if (strains_the_hoop)
          {
            const double r = inputs.evaluation_points[p][0];
            hoop = r > 0. ? inputs.solution_values[p][0] / r : H[0][0];
          }
        const SymmetricTensor<2, 3> s   = material.cauchy_stress(H, hoop);
        const SymmetricTensor<2, 3> dev = deviator(s);
        computed[p][0]                  = s[0][0];
        computed[p][1]                  = s[1][1];
        computed[p][2]                  = s[0][1];
        computed[p][3]                  = s[2][2];
        computed[p][4]                  = std::sqrt(1.5 * (dev * dev));
      }
  }
} // namespace glissade
