#pragma once

#include <deal.II/base/point.h>

#include <glissade/description/kinematics.h>
#include <glissade/description/plane_hypothesis.h>

#include <any>
#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

/*
 * What a .prm file describes, as plain data. Each part declares its own
 * entries and reads them back (declare_parameters and parse_parameters, as
 * the parameter structs of deal.II's step-44), in the source file of its
 * section: source/scene/mesh_section.cc, material_section.cc,
 * body_section.cc, contact_section.cc, load_program_section.cc,
 * output_section.cc. SceneReader runs the passes over the file.
 */
namespace glissade
{
  class SectionReader;

  /**
   * What a body's mesh is made of, as read from its "Mesh" subsection. Only
   * the entries that the chosen generator uses are looked at.
   */
  struct MeshDescription
  {
    std::string               type;
    std::vector<unsigned int> subdivisions;
    /**
     * Mesh/Grading: for each direction of Subdivisions, the ratio of the
     * last interval to the first (a geometric progression; 1 for equal
     * intervals), for the types that take it (rectangle, square, nurbs
     * patch).
     */
    std::array<double, 2> grading = {{1., 1.}};
    std::string           file;
    double                distortion = 0.;
    /**
     * A part of a named boundary under a name of its own (Mesh/Boundary
     * parts): the faces of `boundary` whose centre, in the reference
     * configuration, makes `condition` (an expression of x and y) nonzero.
     */
    struct BoundaryPart
    {
      std::string name, boundary, condition;
    };
    std::vector<BoundaryPart> boundary_parts;
    /**
     * The type's shape (Corner 1, Center, radii, ...), read by the type's
     * own entry of MeshFactory::types() and handed back to its create();
     * opaque here.
     */
    std::any shape;

    /** Body <name>/Mesh (source/scene/mesh_section.cc). */
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /** `where`: "<file>: Body <name>", for messages. */
    void
    parse_parameters(SectionReader &prm, const std::string &where);
  };

  /**
   * One Dirichlet item: where ("left" or "point(x, y)"), which components,
   * and what. Expressions are muParser strings in x, y (reference position)
   * and t (the load program's time).
   */
  struct DirichletDescription
  {
    enum class Kind
    {
      fixed,
      displacement,
      rotation
    };
    Kind        kind = Kind::fixed;
    std::string location;
    bool        x_component = true;
    bool        y_component = true;
    /** "all": also every derivative dof (Hermite), as in the paper's fig 11. */
    bool all_derivatives = false;
    /**
     * "n" or "t" (Fixed only): the displacement normal (or tangential) to
     * the boundary is zero at each node, in the reference configuration's
     * direction there: a roller on a curved boundary. x_component and
     * y_component are then both false.
     */
    enum class Direction
    {
      cartesian,
      normal,
      tangential
    };
    Direction direction = Direction::cartesian;
    /**
     * "symmetry" (Fixed only): a straight boundary along x or y is a
     * symmetry line: the component normal to it is held (BoundaryConditions
     * finds which) and, on a space whose dofs include derivatives, the
     * tangential component's normal derivative (ElementSpace::
     * symmetry_relations). x_component and y_component are then false.
     */
    bool                     symmetry = false;
    std::vector<std::string> expressions; // displacement: one per component
    dealii::Point<2>         rotation_center;
    std::string              angle_expression; // rotation, radians
    std::string              entry;            // the .prm entry it came from
  };

  /** One Neumann item: a point load, a dead traction or a follower pressure. */
  struct NeumannDescription
  {
    enum class Kind
    {
      point_load,
      nodal_loads,
      traction,
      pressure
    };
    Kind                     kind = Kind::point_load;
    std::string              location;
    std::vector<std::string> expressions; // 2 for loads, 1 for pressure
    std::string              entry;
  };

  /** The material of one region of a body (a Gmsh Physical Surface). */
  struct MaterialRegionDescription
  {
    std::string name;
    std::string law;
    double      young_modulus = 1.;
    double      poisson_ratio = 0.3;
    double      density       = 0.;
    /** The law's own settings (LawRegistry), opaque here. */
    std::any law_settings;
  };

  struct MaterialDescription
  {
    std::string law           = "neo-Hookean";
    double      young_modulus = 1.;
    double      poisson_ratio = 0.3;
    /** The law's own settings (LawRegistry), opaque here. */
    std::any        law_settings;
    PlaneHypothesis hypothesis = PlaneHypothesis::plane_strain;
    Kinematics      kinematics = Kinematics::large_strain;
    double          thickness  = 1.;
    /** Mass per unit reference volume: inertia (Time integration) and
     *  Gravity need it; 0 (the default) for a scene without either. */
    double density = 0.;
    /** Regions with a material of their own; other cells take the above. */
    std::vector<MaterialRegionDescription> regions;

    /**
     * Body <name>/Material and a subsection Material <region> for each of
     * `regions` (source/scene/material_section.cc).
     */
    static void
    declare_parameters(dealii::ParameterHandler       &prm,
                       const std::vector<std::string> &regions);
    void
    parse_parameters(SectionReader &prm, const std::string &where);
  };

  /**
   * A body seen from a frame that turns at Omega(t) about e_3 through a
   * centre (Body <name>/Turning frame): the blade in its own frame. Its
   * inertia then has the frame's forces, per unit mass Omega^2 r
   * (centrifugal), -2 Omega e_3 x v (Coriolis) and -dOmega/dt e_3 x r
   * (Euler), r = x - centre the current position.
   */
  struct TurningFrameDescription
  {
    /** Omega, an expression of t in rad/s; empty: the frame is inertial. */
    std::string      angular_velocity;
    dealii::Point<2> centre;
    bool             coriolis = true;

    bool
    active() const
    {
      return !angular_velocity.empty();
    }

    /** The subsection Turning frame of a body
     *  (source/scene/turning_frame_section.cc). */
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(SectionReader &prm, const std::string &where);
  };

  struct BodyDescription
  {
    std::string     name;
    MeshDescription mesh;
    std::string     element_space = "q1";
    /** Element/Degree: the degree of a space not named by it (nurbs). */
    unsigned int                      element_degree = 2;
    MaterialDescription               material;
    std::vector<DirichletDescription> dirichlet;
    std::vector<NeumannDescription>   neumann;
    /** The velocity at t = 0: two expressions of x, y (Initial velocity). */
    std::vector<std::string> initial_velocity = {"0", "0"};
    /** An acceleration field of x, y, t acting on the mass (Boundary
     *  conditions/Gravity); empty for none. */
    std::vector<std::string> gravity;
    /** Springs per unit reference volume holding every point of the body
     *  to where it started (Boundary conditions/Elastic foundation); 0 for
     *  none. */
    double elastic_foundation = 0.;
    /** The frame the body is seen from (Turning frame); inertial if not
     *  active(). */
    TurningFrameDescription turning_frame;

    /**
     * The subsection Body <name>: Mesh, Element, Material, Boundary
     * conditions (source/scene/body_section.cc). `name` is set before
     * parse_parameters.
     */
    static void
    declare_parameters(dealii::ParameterHandler       &prm,
                       const std::vector<std::string> &regions);
    void
    parse_parameters(SectionReader &prm);
  };

  /**
   * The load program: a sequence of stages, each ending at a time t_end and
   * cut into a number of equal increments. Loads and prescribed motions are
   * functions of t, so "load then hold while rotating" is two stages.
   */
  struct LoadProgram
  {
    std::vector<double>       stage_end_times    = {1.};
    std::vector<unsigned int> stage_increments   = {1};
    unsigned int              max_cut_back_depth = 6;

    /** The section Load program (source/scene/load_program_section.cc). */
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(SectionReader &prm);
  };

  /**
   * How time is integrated (section Time integration, source/scene/
   * time_integration_section.cc): quasi-static (the load program's t is a
   * load parameter, no inertia: every scene before issue 35) or an implicit
   * dynamic scheme on the bodies' inertia, the load program's increments
   * then being the time steps.
   */
  struct TimeIntegrationSettings
  {
    /**
     * The scheme's name (TimeSchemeRegistry, source/time/), the settings
     * its own entries gave (read by the scheme's file, as a law's), and
     * whether it integrates the bodies' inertia.
     */
    std::string scheme = "quasi-static";
    std::any    scheme_settings;
    bool        inertia = false;
    /** The mass matrix: consistent (every space) or lumped (HRZ). */
    bool lumped_mass = false;
    /**
     * Khenous, Laborde and Renard's redistributed mass: the value dofs of
     * the nodes on a contact boundary (slave and master) carry no mass,
     * their share moved to the other nodes of their cells.
     */
    bool redistribute_contact_mass = true;
    /** Rayleigh damping C = a_M M (mass-proportional). */
    double mass_damping = 0.;
    /**
     * Rayleigh damping proportional to the stiffness, a_K: a Kelvin-Voigt
     * stress a_K D_0 : dE/dt (ViscousStressPoint).
     */
    double stiffness_damping = 0.;

    bool
    dynamic() const
    {
      return inertia;
    }

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(SectionReader &prm);
  };

  /**
   * The local solver of the condensed contact problem (section Contact
   * solver): the active nodes of all pairs form one problem.
   */
  struct ContactSolverSettings
  {
    /**
     * condensed: the paper's bi-potential solve on W = H K^-1 H^T, dense in
     * the active nodes; sparse: one sparse system of the bodies in contact
     * and the reactions, with an active-set iteration (SparseContactStep),
     * for contacts too large for a dense W.
     */
    enum class Method
    {
      condensed,
      sparse
    };
    Method       method     = Method::condensed;
    double       beta       = 1.;
    double       tolerance  = 1e-10;
    unsigned int max_sweeps = 10000;

    /** The section Contact solver (source/scene/contact_section.cc). */
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(SectionReader &prm);

    /**
     * Old scenes: a pair's own Beta, Tolerance or Maximum sweeps (read in
     * the pair's subsection, `pair_entry` naming it) replaces the
     * section's; each pair's value (its own, or the section's) must be
     * the same, since all pairs form one local problem.
     */
    void
    take_pair_entries(SectionReader &prm, const std::string &pair_entry);
    /** The first pair read, for the message of a pair that disagrees, and
     *  the section's own values (old scenes). */
    std::map<std::string, std::string> set_by_pair;
    std::map<std::string, double>      section_values;
  };

  struct NewtonSettings
  {
    unsigned int max_iterations         = 25;
    double       residual_tolerance     = 1e-9;
    double       displacement_tolerance = 1e-9;
    /** Where the residual already meets its tolerance and only the
     *  displacement test waits for one more correction, that correction is
     *  solved with the last factorisation (NewtonCriterion). */
    bool last_correction_with_previous_tangent = true;

    /** The section Newton (source/scene/load_program_section.cc). */
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(SectionReader &prm);
  };

  struct OutputSettings
  {
    std::string  directory     = "output";
    unsigned int vtu_interval  = 1;    // 0: initial and final states only
    bool         initial_state = true; // the VTU and tables of increment 0
    /** VTU compression: zlib's fastest, its best, or none. */
    enum class Compression
    {
      fast,
      small,
      none
    };
    Compression vtu_compression = Compression::fast;
    /** The fields of the bodies' VTU files: the displacement, and the
     *  Cauchy stress with its von Mises norm. */
    bool         vtu_displacement       = true;
    bool         vtu_stress             = true;
    unsigned int contact_table_interval = 0; // 0: with the VTU files
    /** The contact tables and line meshes per pair, or per body (each
     *  body's slave nodes over all its pairs). */
    enum class ContactTables
    {
      per_pair,
      per_body
    };
    ContactTables            contact_tables = ContactTables::per_pair;
    std::vector<std::string> history;
    bool                     progress = true;
    bool                     plots    = false; // scripts/plot_scene.py
    /** (x column, y column) of history.csv: curves.png, with Plots. */
    std::vector<std::pair<std::string, std::string>> plot_curves;

    /** The section Output (source/scene/output_section.cc). */
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(SectionReader &prm);
  };

  /** Checkpoints of a long run (Simulation::run). */
  struct CheckpointSettings
  {
    unsigned int interval   = 0; // increments between checkpoints; 0: none
    unsigned int stop_after = 0; // stop after this increment; 0: never

    /** The section Checkpoint (source/scene/output_section.cc). */
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /** `load_program`: Stop after increment must lie within it. */
    void
    parse_parameters(SectionReader &prm, const LoadProgram &load_program);
  };

  /**
   * How the bodies' matrices are factorised where the user has a choice:
   * on several processes, MUMPS may keep its factors in files rather than
   * in memory (source/scene/linear_solver_section.cc).
   */
  struct LinearSolverSettings
  {
    bool factors_out_of_core = false;
    /** Where; "" in the file: $TMPDIR, or /tmp. */
    std::string out_of_core_directory;

    /** The section Linear solver. */
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(SectionReader &prm);
  };

  /**
   * A contact pair: the slave nodes of one body's boundary against a master
   * surface, which is another body's boundary or a rigid analytic obstacle.
   */
  struct ContactDescription
  {
    std::string name;
    /**
     * The pair written in the .prm that this one was made from, when its
     * Slave body lists several bodies against a rigid obstacle (one pair a
     * body, "<body> on <pair>"); empty for a pair as written.
     */
    std::string group;
    std::string slave_body;
    std::string slave_boundary;
    /**
     * The master: another body's boundary, or a rigid analytic obstacle
     * (`Master body = rigid`, subsection Obstacle).
     */
    enum class MasterKind
    {
      body,
      obstacle
    };
    MasterKind  master = MasterKind::body;
    std::string master_body; // "rigid" for an obstacle, as the .prm says
    std::string master_boundary;
    std::string surface = "faceted"; // faceted | bspline | hermite
    /** B-spline master: the force goes to the two nodes of the segment
     *  or, through the spline's weights, to its four control points. */
    enum class ForceTransfer
    {
      segment,
      spline
    };
    ForceTransfer force_transfer = ForceTransfer::segment;
    /**
     * The chosen surface's own settings (Faceted vertex rule, ...), read
     * by its plug-in (SurfaceRegistry::Entry::parse_parameters) and
     * handed back to its factory; empty for a surface without options.
     */
    std::any surface_settings;
    /** node-to-segment | mortar (ContactDiscretisation). */
    std::string discretisation = "node-to-segment";
    /**
     * Mortar multipliers (mortar with a NURBS slave): the element-wise dual
     * functions of the slave boundary's R_A, or R_A themselves.
     */
    enum class MortarMultipliers
    {
      dual,
      standard
    };
    MortarMultipliers mortar_multipliers = MortarMultipliers::dual;
    double            alert_distance     = 0.;
    double            friction           = 0.;
    // A rigid obstacle: its kind and its pose (its shape, Normal, Radius,
    // ..., is the kind's own, in surface_settings).
    std::string              obstacle = "line"; // line | disk | hole | casing
    dealii::Point<2>         obstacle_point; // line: a point; disk/hole: centre
    std::vector<std::string> obstacle_motion   = {"0", "0"}; // translation(t)
    std::string              obstacle_rotation = "0"; // angle(t) about point
    std::string              entry;                   // "Contact <name>"

    /** The subsection Contact <name> (source/scene/contact_section.cc). */
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /** `name` is set before; `body_names` are the scene's bodies. */
    void
    parse_parameters(SectionReader                  &prm,
                     const std::vector<std::string> &body_names);

    /**
     * What a pair has beside its two sides (surface, its own entries, force
     * transfer, discretisation, alert distance, friction): the entries that
     * the subsection Automatic contact shares with a pair's.
     */
    static void
    declare_settings(dealii::ParameterHandler &prm);
    /** Reads them; `entry` and `master` are set before. */
    void
    parse_settings(SectionReader &prm);
    /** The sides' checks: bodies that exist, two bodies, boundaries given. */
    void
    check_sides(const std::vector<std::string> &body_names) const;

  private:
    /** The subsection Obstacle of a pair. */
    static void
    declare_obstacle(dealii::ParameterHandler &prm);
  };

  /**
   * Contact found among several bodies (Scene/Contact bodies): each listed
   * body's boundary against every other's, as pairs written by hand would
   * be, with the settings of the subsection Automatic contact
   * (source/scene/automatic_contact_section.cc). The pairs of a couple are
   * made when the bodies come within reach of each other (ContactProblem's
   * broad phase), not for every couple at the start: n bodies have
   * n (n - 1) of them.
   */
  struct AutomaticContact
  {
    /** A listed body and the boundary of it that may touch the others. */
    struct Side
    {
      std::string body;
      std::string boundary;
    };
    std::vector<Side> sides;
    /** Two: each body of a couple slave on the other in turn; one: the
     *  body listed first is the slave. */
    unsigned int passes = 2;
    /** Each listed body's boundary against itself too ("<b> on itself"). */
    bool self_contact = false;
    /** What every pair has beside its sides. */
    ContactDescription settings;
    /** The file, for the entries of messages. */
    std::string file;

    /** No body is listed. */
    bool
    empty() const
    {
      return sides.empty();
    }

    /**
     * The pair of `slave` on `master` (indices into sides), named
     * "<slave> on <master>" ("<b> on itself" when they are one side).
     */
    ContactDescription
    pair(const unsigned int slave, const unsigned int master) const;

    /** Scene/Contact bodies and the subsection Automatic contact. */
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /**
     * Reads them into `automatic` (no side if no body is listed) and
     * returns the pairs made at once: each body on itself under
     * Self-contact. `declared` are the names of the pairs written by hand,
     * which the generated ones must not take.
     */
    static std::vector<ContactDescription>
    parse_parameters(SectionReader                  &prm,
                     const std::vector<std::string> &body_names,
                     const std::vector<std::string> &declared,
                     AutomaticContact               &automatic);
  };

  /** Everything a .prm file describes. */
  struct SceneDescription
  {
    std::string                     source; // file name, for messages
    std::vector<BodyDescription>    bodies;
    std::vector<ContactDescription> contacts;
    /** The couples of Scene/Contact bodies, whose pairs contact makes. */
    AutomaticContact        automatic_contact;
    LoadProgram             load_program;
    TimeIntegrationSettings time_integration;
    NewtonSettings          newton;
    ContactSolverSettings   contact_solver;
    OutputSettings          output;
    CheckpointSettings      checkpoint;
    LinearSolverSettings    linear_solver;
    /** Hash of every value but the Checkpoint section (see SceneReader). */
    std::string fingerprint;
  };
} // namespace glissade
