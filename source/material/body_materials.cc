#include <glissade/base/input_error.h>
#include <glissade/material/body_materials.h>

#include <algorithm>

namespace glissade
{
  using namespace dealii;

  BodyMaterials::BodyMaterials(const MaterialDescription &description,
                               const RegionNames         &regions,
                               const std::string         &mesh_file,
                               const std::string         &where)
    : body_material{Material::create(description.law,
                                     description.young_modulus,
                                     description.poisson_ratio,
                                     description.hypothesis,
                                     description.kinematics,
                                     description.law_settings),
                    description.young_modulus,
                    "Material",
                    description.density}
  {
    for (const MaterialRegionDescription &region : description.regions)
      {
        const auto id = regions.find(region.name);
        if (id == regions.end())
          {
            std::string known;
            for (const auto &[name, tag] : regions)
              known += (known.empty() ? "'" : ", '") + name + "'";
            throw InputError(
              where + "/Material/Regions",
              "'" + region.name + "' is not a Physical Surface of " +
                (mesh_file.empty() ? std::string("this mesh (regions come "
                                                 "from Gmsh files)") :
                                     "'" + mesh_file + "'") +
                (known.empty() ? std::string(" (it has none)") :
                                 " (its Physical Surfaces: " + known + ")"));
          }
        region_materials.emplace(id->second,
                                 Entry{Material::create(region.law,
                                                        region.young_modulus,
                                                        region.poisson_ratio,
                                                        description.hypothesis,
                                                        description.kinematics,
                                                        region.law_settings),
                                       region.young_modulus,
                                       "Material " + region.name,
                                       region.density});
      }
  }



  const Material &
  BodyMaterials::of_cell(const dealii::types::material_id id) const
  {
    const auto region = region_materials.find(id);
    return region == region_materials.end() ? body_material.material :
                                              region->second.material;
  }



  std::pair<double, std::string>
  BodyMaterials::young_modulus_of_cell(
    const dealii::types::material_id id) const
  {
    const auto   region = region_materials.find(id);
    const Entry &entry =
      region == region_materials.end() ? body_material : region->second;
    return {entry.young_modulus, entry.subsection + "/Young modulus"};
  }



  double
  BodyMaterials::density_of_cell(const dealii::types::material_id id) const
  {
    const auto region = region_materials.find(id);
    return region == region_materials.end() ? body_material.density :
                                              region->second.density;
  }



  double
  BodyMaterials::largest_young_modulus() const
  {
    double largest = body_material.young_modulus;
    for (const auto &[id, entry] : region_materials)
      largest = std::max(largest, entry.young_modulus);
    return largest;
  }
} // namespace glissade
