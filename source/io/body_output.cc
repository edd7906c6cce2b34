#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <glissade/base/processes.h>
#include <glissade/body/body.h>
#include <glissade/io/atomic_file.h>
#include <glissade/io/body_output.h>
#include <glissade/io/stress_postprocessor.h>

#include <iomanip>
#include <sstream>

namespace glissade
{
  using namespace dealii;

  namespace
  {
    /**
     * A nodal vector field (displacement, contact force) from the value
     * components (Hermite: components 0 and 3 of 6; Lagrange: 0 and 1).
     */
    class NodalDisplacement : public DataPostprocessorVector<2>
    {
    public:
      explicit NodalDisplacement(const unsigned int per_dim,
                                 const std::string &name = "displacement")
        : DataPostprocessorVector<2>(name, update_values)
        , per_dim(per_dim)
      {}

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<2> &inputs,
        std::vector<Vector<double>>              &computed) const override
      {
        for (unsigned int p = 0; p < computed.size(); ++p)
          for (unsigned int c = 0; c < 2; ++c)
            computed[p][c] = inputs.solution_values[p][c * per_dim];
      }

    private:
      const unsigned int per_dim;
    };
  } // namespace

  std::string
  write_body_vtu(const Body           &body,
                 const std::string    &directory,
                 const unsigned int    index,
                 const OutputSettings &settings)
  {
    const ElementSpace &element_space = body.space();
    // (the values at the finite element's nodes, which DataOut reads: the
    // displacement itself but for a NURBS body)
    const Vector<double> &solution      = body.nodal_displacement();
    const BodyInertia    *inertia_terms = body.inertia();
    const unsigned int    per_dim = element_space.components_per_displacement();
    StressPostprocessor   stress(body.materials(),
                               per_dim,
                               body.hypothesis().strains_the_hoop());
    NodalDisplacement     nodal_displacement(per_dim);
    DataOut<2>            data_out;
    data_out.attach_dof_handler(body.dof_handler());
    // (the fields the scene asks for: Output/VTU fields)
    if (settings.vtu_displacement && per_dim == 1)
      {
        const std::vector<std::string> names(2, "displacement");
        const std::vector<
          DataComponentInterpretation::DataComponentInterpretation>
          interpretation(
            2, DataComponentInterpretation::component_is_part_of_vector);
        data_out.add_data_vector(solution,
                                 names,
                                 DataOut<2>::type_dof_data,
                                 interpretation);
      }
    else if (settings.vtu_displacement)
      data_out.add_data_vector(solution, nodal_displacement);
    if (settings.vtu_stress)
      data_out.add_data_vector(solution, stress);
    // A dynamic scheme's velocity and acceleration, beside the
    // displacement (the same fields, on the same nodes).
    NodalDisplacement nodal_velocity(per_dim, "velocity"),
      nodal_acceleration(per_dim, "acceleration");
    if (inertia_terms && settings.vtu_displacement)
      {
        if (per_dim == 1)
          for (const auto &[vector, name] :
               {std::make_pair(&inertia_terms->velocity(), "velocity"),
                std::make_pair(&inertia_terms->acceleration(), "acceleration")})
            data_out.add_data_vector(
              *vector,
              std::vector<std::string>(2, name),
              DataOut<2>::type_dof_data,
              std::vector<
                DataComponentInterpretation::DataComponentInterpretation>(
                2, DataComponentInterpretation::component_is_part_of_vector));
        else
          {
            data_out.add_data_vector(inertia_terms->velocity(), nodal_velocity);
            data_out.add_data_vector(inertia_terms->acceleration(),
                                     nodal_acceleration);
          }
      }
    // No nodal forces here: DataOut writes each node once per cell, so a
    // force field summed over the points would count a node up to four
    // times. The contact forces are in the contact surface output
    // (ContactSurfaceOutput), each node once.
    const unsigned int degree =
      per_dim == 1 ? element_space.finite_element().degree : 1;
    // No time stamp in the file: the same scene must give the same bytes
    // (ctest -R determinism).
    DataOutBase::VtkFlags flags;
    flags.print_date_and_time = false;
    // deal.II's default is zlib's level 9, which made writing the VTU files
    // a third of the rings' run; level 1 writes them 5.6 times faster for
    // files 0.6 % larger (doc/performance.md).
    using Compression             = OutputSettings::Compression;
    const Compression compression = settings.vtu_compression;
    flags.compression_level       = compression == Compression::small ?
                                      DataOutBase::VtkFlags::best_compression :
                                    compression == Compression::none ?
                                      DataOutBase::VtkFlags::no_compression :
                                      DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(flags);
    // This process's share of the cells (those it integrates,
    // Body::is_own_cell: all of them on one process).
    data_out.set_cell_selection(
      [&body](const Triangulation<2>::cell_iterator &cell) {
        return body.is_own_cell(cell);
      });
    data_out.build_patches(element_space.mapping(),
                           degree,
                           DataOut<2>::curved_inner_cells);

    std::ostringstream stem;
    stem << body.name() << "-" << std::setw(5) << std::setfill('0') << index;
    const processes::VtuFiles files = processes::vtu_files(stem.str());
    AtomicFile                file(directory + "/" + files.own_piece);
    file.write_and_commit([&](std::ostream &out) { data_out.write_vtu(out); });
    if (!files.record.empty() && processes::writes_files())
      {
        // (deal.II 9.4 stamps the record with the date whatever the flags
        // say: taken out, so that a scene gives the same bytes every time)
        std::ostringstream text;
        data_out.write_pvtu_record(text, files.pieces);
        std::string       record_text = text.str();
        const std::size_t comment     = record_text.find("<!--");
        const std::size_t comment_end = record_text.find("-->\n", comment);
        if (comment != std::string::npos && comment_end != std::string::npos)
          record_text.erase(comment, comment_end + 4 - comment);
        AtomicFile record(directory + "/" + files.record);
        record.write_and_commit([&](std::ostream &out) { out << record_text; });
      }
    return files.whole();
  }
} // namespace glissade
