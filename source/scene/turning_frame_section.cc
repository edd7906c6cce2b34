// Body <name>/Turning frame: the frame a body is seen from, turning at
// Omega(t) about e_3 (a blade in its own frame, its centrifugal stiffening
// and spin softening, and the Coriolis forces).

#include <deal.II/base/parameter_handler.h>

#include <glissade/base/input_error.h>
#include <glissade/base/text.h>
#include <glissade/description/scene_description.h>
#include <glissade/scene/section_reader.h>

namespace glissade
{
  using namespace dealii;

  void
  TurningFrameDescription::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Turning frame");
    prm.declare_entry(
      "Angular velocity",
      "",
      Patterns::Anything(),
      "The body is seen from a frame turning at this angular velocity about "
      "e_3 through Centre (rad/s, an expression of t; positive "
      "anticlockwise). Its inertia (a dynamic scheme: Time integration) "
      "then has the frame's forces per unit mass: Omega^2 r, centrifugal, "
      "with r the current position from Centre (its dependence on the "
      "displacement is the spin softening; the stress it makes, the "
      "centrifugal stiffening), -2 Omega e_3 x v (Coriolis) and -dOmega/dt "
      "e_3 x r (Euler). Empty: an inertial frame.");
    prm.declare_entry("Centre",
                      "0, 0",
                      Patterns::Anything(),
                      "The point the frame turns about: 'x, y'.");
    prm.declare_entry("Coriolis",
                      "true",
                      Patterns::Bool(),
                      "Whether the Coriolis forces act (false: the "
                      "centrifugal and Euler forces alone, as a model that "
                      "drops them).");
    prm.leave_subsection();
  }



  void
  TurningFrameDescription::parse_parameters(SectionReader     &prm,
                                            const std::string &where)
  {
    prm.enter_subsection("Turning frame");
    const std::string entry = where + "/Turning frame/";
    angular_velocity        = text::trim(prm.get("Angular velocity"));
    centre   = entry_format::coordinates(prm.get("Centre"), entry + "Centre");
    coriolis = prm.get_bool("Coriolis");
    prm.leave_subsection();
    if (active())
      entry_format::check_expressions({angular_velocity},
                                      entry + "Angular velocity");
  }
} // namespace glissade
