#include <deal.II/numerics/data_out.h>

#include <glissade/body/body.h>
#include <glissade/io/atomic_file.h>
#include <glissade/io/stress_postprocessor.h>

#include <iomanip>
#include <sstream>

namespace glissade
{
  std::string
  Body::write_vtu(const std::string &directory, const unsigned int index) const
  {
    StressPostprocessor stress(body_material);
    DataOut<2>          data_out;
    data_out.attach_dof_handler(dofs);
    const std::vector<std::string> names(2, "displacement");
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(2,
                     DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(solution,
                             names,
                             DataOut<2>::type_dof_data,
                             interpretation);
    data_out.add_data_vector(solution, stress);
    const unsigned int degree = element_space->finite_element().degree;
    data_out.build_patches(element_space->mapping(),
                           degree,
                           DataOut<2>::curved_inner_cells);

    std::ostringstream name;
    name << description.name << "-" << std::setw(5) << std::setfill('0')
         << index << ".vtu";
    AtomicFile file(directory + "/" + name.str());
    data_out.write_vtu(file.stream());
    file.commit();
    return name.str();
  }
} // namespace glissade
