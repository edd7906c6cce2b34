#pragma once

#include <deal.II/base/types.h>

#include <glissade/description/scene_description.h>
#include <glissade/material/material.h>
#include <glissade/mesh/mesh_labels.h>

#include <map>
#include <string>

namespace glissade
{
  /**
   * The materials of one body: its Material subsection, and one material
   * per region (a Gmsh Physical Surface named in Material/Regions), looked
   * up by the cells' material id.
   */
  class BodyMaterials
  {
  public:
    /**
     * `regions` maps the mesh's region names to material ids; `where` names
     * the body ("file.prm: Body bar"), for messages.
     */
    BodyMaterials(const MaterialDescription &description,
                  const RegionNames         &regions,
                  const std::string         &mesh_file,
                  const std::string         &where);

    /** The material of the cells with this material id. */
    const Material &
    of_cell(const dealii::types::material_id id) const;

    /** The body's own (the Material subsection). */
    const Material &
    of_body() const
    {
      return body_material.material;
    }

    /** The Young modulus of the cells with this id and the entry it is. */
    std::pair<double, std::string>
    young_modulus_of_cell(const dealii::types::material_id id) const;

    /** The density of the cells with this material id (Material/Density). */
    double
    density_of_cell(const dealii::types::material_id id) const;

    /** The largest Young modulus of any region (for force scales). */
    double
    largest_young_modulus() const;

  private:
    struct Entry
    {
      Material    material;
      double      young_modulus;
      std::string subsection; // "Material" or "Material <region>"
      double      density = 0.;
    };

    Entry                                       body_material;
    std::map<dealii::types::material_id, Entry> region_materials;
  };
} // namespace glissade
