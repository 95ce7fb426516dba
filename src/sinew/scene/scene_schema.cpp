/// @file scene_schema.cpp
/// The scene schema: every key of a scene file, its type, default, range and meaning.

#include "sinew/scene/scene_schema.hpp"

#include "sinew/fem/motion.hpp"
#include "sinew/material/material_spec.hpp"
#include "sinew/mesh/generate.hpp"
#include "sinew/scene/scene_config.hpp"
#include "sinew/scene/schema_builder.hpp"

namespace sinew::scene {

using nlohmann::json;

const char* predictor_name(solver::LoadSteppingOptions::Predictor predictor) {
  switch (predictor) {
    case solver::LoadSteppingOptions::Predictor::None: return "none";
    case solver::LoadSteppingOptions::Predictor::TwoPoint: return "two-point";
    case solver::LoadSteppingOptions::Predictor::Tangent: return "tangent";
  }
  return "?";
}

const char* line_search_name(solver::NewtonOptions::LineSearchRule rule) {
  switch (rule) {
    case solver::NewtonOptions::LineSearchRule::Energy: return "energy";
    case solver::NewtonOptions::LineSearchRule::Residual: return "residual";
  }
  return "?";
}

const char* linear_solver_name(solver::LinearSolverOptions::Kind kind) {
  switch (kind) {
    case solver::LinearSolverOptions::Kind::Cholmod: return "cholmod";
    case solver::LinearSolverOptions::Kind::Gmres: return "gmres";
    case solver::LinearSolverOptions::Kind::ConjugateGradient: return "cg";
  }
  return "?";
}

namespace {

using namespace schema_builder;  // NOLINT(google-build-using-namespace)

// ---------------------------------------------------------------- bounds
// Every number is bounded, in the scene's own units, so that the products the solver forms
// (modulus x strain, penalty x depth^2 x area, density x gravity x volume, ...) stay finite and
// Gmsh's geometry well conditioned; real scenes lie orders of magnitude inside
// (docs/scene-reference.md, Conventions: Bounds).
constexpr double kMaxLength = 1e6;         ///< coordinates, lengths, displacements, direction components (length)
constexpr double kMinElementSize = 1e-9;   ///< smallest element_size (length); the tet estimate bounds it further
constexpr double kMaxPhysical = 1e12;      ///< moduli, stresses, densities, gravity, forces, damping (their units)
constexpr double kMaxPenalty = 1e15;       ///< contact penalty (force / length^3): E / h of 1 TPa over 1 mm, in SI
constexpr double kMaxScale = 1e6;          ///< contact penalty factors (dimensionless)
constexpr double kMaxExponent = 1e3;       ///< exponents beta of exp(beta (...)) (dimensionless)
constexpr double kMaxAngle = 1e5;          ///< angles (degrees): about 280 turns
constexpr double kMaxFactor = 1e6;         ///< amplitude points: lambda and factor (dimensionless)
constexpr double kMinStep = 1e-12;         ///< smallest min_step (fraction of an increment): 40 halvings
constexpr double kMaxGrowth = 1e3;         ///< step growth factors
constexpr double kMinTolerance = 1e-16;    ///< relative tolerances: about the double's epsilon
constexpr double kMinTime = 1e-15;         ///< time steps and intervals (time)
constexpr double kMaxTime = 1e12;          ///< end time and time steps (time)
constexpr int kMaxIncrements = 1000000;    ///< load increments, output.every
constexpr int kMaxIterations = 100000;     ///< Newton iteration counts
constexpr int kMaxCuts = 1000;             ///< failed attempts counted before a snap-through attempt
constexpr int kMaxHalvings = 200;          ///< line-search halvings (2^-200 ~ 1e-60)
constexpr int kMaxLinearIterations = 1000000;  ///< iterative linear solvers' iterations
constexpr int kMaxRestart = 1000;          ///< GMRES restart length (that many vectors of every unknown)

// ---------------------------------------------------------------- definitions

SchemaNode amplitude_definition() {
  SchemaNode pair = array("", "[lambda, factor]", number("", "lambda or factor").within(kMaxFactor)).items(2, 2);
  return array("", "Piecewise-linear factor through [lambda, factor] points, lambda strictly increasing, held "
                   "constant outside them; when omitted the factor ramps as a(lambda) = lambda",
               pair)
      .items(1);
}

SchemaNode motion_definition() {
  const fem::RigidMotion defaults;
  return object("",
                "A rigid motion reached at the end of the load (lambda = 1), scaled by its amplitude: "
                "x = R(a angle) (X - point) + point + a translation",
                {
                    vec3("translation", "final translation (length)").within(kMaxLength).fallback(vec3_json(defaults.translation)),
                    object("rotation", "final rotation about an axis through a point (none when omitted)",
                           {
                               vec3("axis", "rotation axis direction, normalized on use").required().nonzero().within(kMaxLength),
                               vec3("point", "a point on the axis (length)").within(kMaxLength).fallback(vec3_json(defaults.axis_point)),
                               number("angle_deg", "final angle (degrees, right-hand rule)").required().within(kMaxAngle),
                           }),
                    ref("amplitude", "factor a(lambda) applied to angle and translation", "amplitude"),
                });
}

SchemaNode node_selector_definition() {
  const NodeSelector defaults;
  return one_of(
      "", "Chooses nodes of one body by rest position (after the body's transform), set or region",
      {
          string("body", "body name; may be omitted when the scene has exactly one body").non_empty(),
          string("set", "a node set of the mesh, or the nodes of the face set of that name").non_empty(),
          string("region", "the nodes of the tets of this mesh region").non_empty(),
          object("box", "nodes with min - padding <= X <= max + padding, componentwise",
                 {
                     vec3("min", "lower corner (length)").required().within(kMaxLength),
                     vec3("max", "upper corner (length)").required().within(kMaxLength),
                     number("padding", "tolerance added on every side (length)").min(0).max(kMaxLength).fallback(defaults.tolerance),
                 }),
          object("plane", "nodes with |n . (X - point)| <= tolerance",
                 {
                     vec3("point", "a point of the plane (length)").required().within(kMaxLength),
                     vec3("normal", "plane normal n, normalized on use").required().nonzero().within(kMaxLength),
                     number("tolerance", "distance tolerance (length)").min(0).max(kMaxLength).fallback(defaults.tolerance),
                 }),
          boolean("all", "every node of the body").allowed({true}),
      },
      {"set", "region", "box", "plane", "all"});
}

SchemaNode shape_definition() {
  const mesh::Shape defaults;
  return one_of("",
                "A solid for mesh generation: a primitive or a boolean combination, optionally moved by a rigid "
                "transform",
                {
                    object("box", "box, axis-aligned before the shape's transform",
                           {
                               vec3("min", "lower corner (length)").required().within(kMaxLength),
                               vec3("max", "upper corner, > min componentwise (length)").required().within(kMaxLength),
                           }),
                    object("sphere", "ball",
                           {
                               vec3("center", "center (length)").required().within(kMaxLength),
                               number("radius", "radius (length)").required().above(0).max(kMaxLength),
                           }),
                    object("cylinder", "solid cylinder",
                           {
                               vec3("base", "center of the base disk (length)").required().within(kMaxLength),
                               vec3("axis", "from the base center to the top center; its length is the height (length)")
                                   .within(kMaxLength)
                                   .required()
                                   .nonzero(),
                               number("radius", "radius (length)").required().above(0).max(kMaxLength),
                           }),
                    object("torus",
                           "solid torus, or the segment of one swept through angle_deg (a bent rod with flat "
                           "disk ends)",
                           {
                               vec3("center", "center of the torus, on its axis (length)").required().within(kMaxLength),
                               vec3("axis",
                                    "normal of the plane of the centre circle; the sweep turns about it by the "
                                    "right-hand rule")
                                   .within(kMaxLength)
                                   .required()
                                   .nonzero(),
                               number("radius", "major radius: of the circle through the tube centres (length)")
                                   .max(kMaxLength)
                                   .required()
                                   .above(0),
                               number("minor_radius", "tube radius, < radius (length)").required().above(0).max(kMaxLength),
                               number("angle_deg", "swept angle (degrees), from start_direction about axis")
                                   .above(0)
                                   .max(360)
                                   .fallback(defaults.angle_deg),
                               vec3("start_direction",
                                    "direction from the center to the centre of the tube's first end (its part "
                                    "perpendicular to axis counts); default: +x projected onto the torus plane, or +y "
                                    "projected when the axis is along x")
                                   .within(kMaxLength)
                                   .nonzero(),
                           }),
                    array("union", "all shapes fused", ref("", "", "shape")).items(1),
                    array("difference", "the first shape minus all the others", ref("", "", "shape")).items(2),
                    array("intersection", "the region common to all the shapes", ref("", "", "shape")).items(2),
                    object("transform",
                           "rigid transform of this shape, applied after it is built (and after its children's own "
                           "transforms): first rotate, then translate",
                           {
                               object("rotate", "rotation about an axis through a point (none when omitted)",
                                      {
                                          vec3("axis", "rotation axis direction, normalized on use")
                                              .within(kMaxLength)
                                              .required()
                                              .nonzero(),
                                          number("angle_deg", "angle (degrees, right-hand rule)").required().within(kMaxAngle),
                                          vec3("center", "a point on the axis (length)")
                                              .within(kMaxLength)
                                              .fallback(vec3_json(defaults.rotation_center)),
                                      }),
                               vec3("translate", "translation, applied after the rotation (length)")
                                   .within(kMaxLength)
                                   .fallback(vec3_json(defaults.translation)),
                           }),
                },
                {"box", "sphere", "cylinder", "torus", "union", "difference", "intersection"});
}

// ---------------------------------------------------------------- top-level parts

SchemaNode material_schema() {
  const material::MooneyRivlinParams mooney_rivlin;
  const material::FiberParams fiber;
  Key m = object("", "A hyperelastic law (docs/theory.md); stresses in the scene's stress unit",
                 {
                     string("law", "the strain-energy function")
                         .required()
                         .allowed({"mooney-rivlin", "veronda-westmann", "neo-hookean"}),
                     object("fiber",
                            "fiber reinforcement added to the law: psi_f = alpha exp(beta (lambda^2 - 1)) - alpha beta "
                            "lambda^2 + const, lambda^2 = d . C d",
                            {
                                number("alpha", "fiber stiffness (stress)").required().min(0).max(kMaxPhysical),
                                number("beta", "fiber exponent (dimensionless)").required().above(0).max(kMaxExponent),
                                vec3("direction", "rest fiber direction d (normalized on use); regions may override it")
                                    .within(kMaxLength)
                                    .nonzero()
                                    .fallback(vec3_json(fiber.direction)),
                            }),
                 });
  m.node.tag_key = "law";
  m.node.variants = {
      {"mooney-rivlin",
       "psi = C1 (I1-3) + C2 (I2-3) + a (I3-1) - (C1 + 2 C2 + a) ln I3",
       {
           number("C1", "first Mooney-Rivlin constant (stress)").required().above(0).max(kMaxPhysical),
           number("C2", "second Mooney-Rivlin constant (stress)").min(0).max(kMaxPhysical).fallback(mooney_rivlin.C2),
           number("a", "compressibility (stress)").required().above(0).max(kMaxPhysical),
       }},
      {"veronda-westmann",
       "psi = alpha (exp(beta (I1-3)) - 1) - (alpha beta / 2)(I2-3) + a (I3-1) - a ln I3",
       {
           number("alpha", "stiffness (stress)").required().above(0).max(kMaxPhysical),
           number("beta", "exponent (dimensionless)").required().above(0).max(kMaxExponent),
           number("a", "compressibility (stress)").required().above(0).max(kMaxPhysical),
       }},
      {"neo-hookean",
       "psi = mu/2 (I1-3) - mu ln J + lambda/2 (ln J)^2",
       {
           number("mu", "shear modulus (stress)").required().above(0).max(kMaxPhysical),
           number("lambda", "first Lame parameter (stress)").required().min(0).max(kMaxPhysical),
       }},
  };
  return m;
}

SchemaNode body_schema() {
  const MeshSourceConfig mesh_defaults;
  const mesh::GenerateOptions generate_defaults;
  const RegionConfig region_defaults;
  return object(
      "", "A solid body: its mesh, placement and what each mesh region is made of",
      {
          string("name", "unique body name; regions and sets are called \"<body>/<name>\" in outputs")
              .required()
              .non_empty(),
          one_of("mesh", "where the tetrahedral mesh comes from",
                 {
                     string("file", "Gmsh .msh file (format 2 or 4); relative paths start at the scene file's directory")
                         .non_empty(),
                     object("generate", "mesh primitive solids with Gmsh (OpenCASCADE)",
                            {
                                number("element_size", "target tet edge length (length)").required().min(kMinElementSize).max(kMaxLength),
                                integer("optimize_passes", "Gmsh tet optimization passes")
                                    .min(0)
                                    .max(100)
                                    .fallback(generate_defaults.optimize_passes),
                                number("elements_per_turn",
                                       "curved surfaces get at least this many elements per full turn, down to "
                                       "element_size / 10 (thin rods: lower it); 0 = element_size alone")
                                    .min(0)
                                    .max(1000)
                                    .fallback(generate_defaults.elements_per_turn),
                                array("parts",
                                      "named solids, each a region; fragmented into one conforming mesh (where they "
                                      "overlap, the first listed wins); each part's boundary is also the face set "
                                      "\"<region>.surface\"",
                                      object("", "a named solid",
                                             {
                                                 string("region", "region name of this part").required().non_empty(),
                                                 ref("shape", "its solid", "shape").required(),
                                             }))
                                    .required()
                                    .items(1),
                            }),
                 },
                 {"file", "generate"})
              .required(),
          object("transform", "rigid placement of the mesh: rotate about the origin, then translate",
                 {
                     vec3("translate", "translation (length)").within(kMaxLength).fallback(vec3_json(mesh_defaults.translate)),
                     object("rotate", "rotation about an axis through the origin",
                            {
                                vec3("axis", "rotation axis").nonzero().within(kMaxLength).fallback(vec3_json(mesh_defaults.rotate_axis)),
                                number("angle_deg", "angle (degrees, right-hand rule)").within(kMaxAngle).fallback(mesh_defaults.rotate_angle),
                            })
                         .fallback(json::object()),
                 })
              .fallback(json::object()),
          map("regions",
              "mesh region name -> what it is made of; the entry \"*\" applies to every mesh region without its own "
              "entry",
              object("", "a deformable region (\"material\") or a rigid one (\"rigid\")",
                     {
                         string("material", "name of a material (a key of \"materials\"); omit for rigid regions")
                             .non_empty(),
                         either("rigid",
                                "the region moves as one rigid body: \"fixed\" (stays in place), \"free\" (moved by "
                                "contact and loads) or {\"prescribed\": motion}",
                                {
                                    string("", "fixed or free").allowed({"fixed", "free"}),
                                    one_of("", "a prescribed rigid motion",
                                           {ref("prescribed", "the motion", "motion")}, {"prescribed"}),
                                }),
                         number("density", "mass per rest volume (mass / length^3)")
                             .max(kMaxPhysical)
                             .min(0)
                             .fallback(region_defaults.density),
                         vec3("fiber_direction", "overrides the material's fiber direction in this region").nonzero().within(kMaxLength),
                         number("contact_penalty_scale",
                                "factor on the contact penalty where this region's surface or tets take part; two "
                                "parts in contact use the smaller of their factors, so stiff parts (e.g. two rigid "
                                "bones) can meet with a stiffer penalty than soft tissue against either")
                             .max(kMaxScale)
                             .above(0)
                             .fallback(region_defaults.contact_penalty_scale),
                     }))
              .required()
              .items(1),
          object("contact",
                 "how this body's material depth is defined (used when the scene has a \"contact\" section); by "
                 "default the depth of a node is its rest distance to the body's whole boundary",
                 {
                     string("depth_face_set",
                            "measure depth from this face set only (a mesh face set of the body, or "
                            "\"<region>.surface\" of a generated part)")
                         .non_empty(),
                     string("depth_region",
                            "measure depth from the boundary faces of the tets of this region only")
                         .non_empty(),
                     array("depth_nodes",
                           "measure depth from the boundary faces whose three nodes are all chosen by one of these "
                           "selectors (e.g. a plane: only the face that touches; symmetry planes and free sides then "
                           "do not count)",
                           ref("", "a node selector (its \"body\" is this body)", "node_selector"))
                         .items(1),
                     string("depth_file",
                            "nodal depths instead (text: one number per node of the body's mesh, in mesh order; "
                            "relative paths start at the scene file's directory)")
                         .non_empty(),
                     string("depth_field",
                            "nodal depths instead, from this node field of the body's mesh file (a Gmsh "
                            "$NodeData view of this name: one scalar per node, its first time step; every "
                            "node of the mesh needs a finite value >= 0)")
                         .non_empty(),
                 })
              .fallback(json::object()),
      });
}

SchemaNode contact_schema() {
  const ContactConfig defaults;
  return object(
      "contact",
      "material-depth contact between all bodies, self-contact included (docs/theory.md): the energy "
      "(penalty/2) * integral of depth^2 over every boundary-triangle / tet intersection. Omit for no contact.",
      {
          string("method", "\"area\": exact integral over triangle-tet intersections (continuous forces); "
                           "\"point\": the seed's collocation at triangle vertices (baseline)")
              .allowed({"area", "point"})
              .fallback("area"),
          string("hessian",
                 "contact stiffness: \"exact\" (the exact second derivative), \"projected\" (exact, each pair "
                 "projected onto the positive semi-definite cone) or \"gauss-newton\" (positive semi-definite, "
                 "frozen areas; cheapest, converges slowly where contact areas change)")
              .allowed({"exact", "projected", "gauss-newton"})
              .fallback(defaults.hessian == contact::PairHessian::Exact       ? "exact"
                        : defaults.hessian == contact::PairHessian::Projected ? "projected"
                                                                              : "gauss-newton"),
          number("penalty",
                 "penalty for every pair of bodies (force / length^3: a penetration g meets a pressure of about "
                 "penalty * g); default: penalty_scale * E / h per pair of bodies")
              .max(kMaxPenalty)
              .above(0),
          number("penalty_scale",
                 "automatic penalty = penalty_scale * E / h, E the smaller initial Young's modulus of the two bodies "
                 "(rigid bodies take the other's), h the smaller mean boundary edge length")
              .max(kMaxScale)
              .above(0)
              .fallback(defaults.penalty_scale),
          boolean("self_contact", "a body's surface may also penetrate the same body").fallback(defaults.self_contact),
          array("pairs", "per pair of bodies: a penalty of its own, or no contact",
                object("", "one pair of bodies (the same name twice for self-contact)",
                       {
                           array("bodies", "two body names", string("", "body name").non_empty()).required().items(2, 2),
                           number("penalty", "penalty of this pair (force / length^3)").above(0).max(kMaxPenalty),
                           boolean("enabled", "false: these bodies do not touch").fallback(true),
                       }))
              .fallback(json::array()),
      });
}

SchemaNode boundary_condition_schema() {
  const BoundaryConditionConfig defaults;
  Key bc = object("", "Constrains the motion of nodes",
                  {
                      string("name", "unique name, used in logs and reaction-force outputs").required().non_empty(),
                      string("type", "kind of constraint").required().allowed({"fixed", "prescribed", "planar"}),
                      ref("nodes", "the constrained nodes", "node_selector").required(),
                  });
  bc.node.tag_key = "type";
  bc.node.variants = {
      {"fixed", "the nodes stay at their rest positions", {}},
      {"prescribed", "the nodes follow a rigid motion", {ref("motion", "the prescribed motion", "motion").required()}},
      {"planar",
       "the nodes move only in a plane: n . (x - X) = displacement * amplitude(lambda)",
       {
           vec3("normal", "plane normal n, normalized on use").required().nonzero().within(kMaxLength),
           number("displacement", "final displacement along n (length)").within(kMaxLength).fallback(defaults.displacement),
           ref("amplitude", "factor applied to the displacement", "amplitude"),
       }},
  };
  return bc;
}

SchemaNode loads_schema() {
  const LoadsConfig defaults;
  return object("loads", "external loads",
                {
                    vec3("gravity", "gravitational acceleration (length / time^2)").within(kMaxPhysical).fallback(vec3_json(defaults.gravity)),
                    array("forces", "forces spread equally over node sets",
                          object("", "a force",
                                 {
                                     string("name", "name, used in logs").required().non_empty(),
                                     ref("nodes", "the loaded nodes", "node_selector").required(),
                                     vec3("total_force", "total force over all selected nodes (force)").required().within(kMaxPhysical),
                                     ref("amplitude", "factor applied to the force", "amplitude"),
                                 }))
                        .fallback(json::array()),
                })
      .fallback(json::object());
}

SchemaNode solver_schema() {
  const solver::StaticSolverOptions defaults;
  const auto& stepping = defaults.stepping;
  const auto& newton = defaults.newton;
  const auto& linear = defaults.linear;
  using Predictor = solver::LoadSteppingOptions::Predictor;
  using Rule = solver::NewtonOptions::LineSearchRule;
  using Kind = solver::LinearSolverOptions::Kind;
  return object(
             "solver", "static solver: adaptive load stepping, Newton, line search, linear solver",
             {
                 integer("increments", "load increments (an output after each)").min(1).max(kMaxIncrements).fallback(stepping.increments),
                 string("predictor", "initial guess of each step: tangent (linearized response from the last factorization), two-point (the seed's extrapolation of the last two states) or none")
                     .allowed({predictor_name(Predictor::None), predictor_name(Predictor::TwoPoint),
                               predictor_name(Predictor::Tangent)})
                     .fallback(predictor_name(stepping.predictor)),
                 number("min_step", "smallest load step when halving, as a fraction of an increment")
                     .min(kMinStep)
                     .max(1)
                     .fallback(stepping.min_step),
                 number("growth", "step growth factor after an easy step").min(1).max(kMaxGrowth).fallback(stepping.growth),
                 integer("easy_iterations", "Newton iterations at or below which a step counts as easy")
                     .max(kMaxIterations)
                     .min(0)
                     .fallback(stepping.easy_iterations),
                 integer("snap_through_after_cuts", "after this many failed attempts in a row, the next attempt gets snap_through_iterations Newton iterations (passes limit points: a buckle or a fold snapping through, where no smaller step helps); 0 = off")
                     .max(kMaxCuts)
                     .min(0)
                     .fallback(stepping.snap_through_after_cuts),
                 integer("snap_through_iterations", "Newton iterations of that attempt")
                     .max(kMaxIterations)
                     .min(1)
                     .fallback(stepping.snap_through_iterations),
                 object("newton", "Newton iterations of one load step",
                        {
                            integer("max_iterations", "iterations before the step fails and is halved")
                                .max(kMaxIterations)
                                .min(1)
                                .fallback(newton.max_iterations),
                            number("residual_tolerance", "converged when |residual| <= this * force scale")
                                .min(kMinTolerance)
                                .fallback(newton.residual_tolerance),
                            number("increment_tolerance",
                                   "... and the largest node displacement of the last iteration <= this * bounding-box "
                                   "diagonal")
                                .min(kMinTolerance)
                                .fallback(newton.increment_tolerance),
                            string("line_search", "accept a step when the energy decreases, or when the residual does")
                                .allowed({line_search_name(Rule::Energy), line_search_name(Rule::Residual)})
                                .fallback(line_search_name(newton.line_search)),
                            integer("max_line_search_steps", "step halvings before the iteration fails")
                                .max(kMaxHalvings)
                                .min(0)
                                .fallback(newton.max_line_search_steps),
                            number("quasi_viscosity",
                                   "K + D/dt with D_a = this * (volume around node a)^(1/3) (stress * length); 0 = off")
                                .max(kMaxPhysical)
                                .min(0)
                                .fallback(newton.quasi_viscosity),
                            boolean("project_hessians",
                                    "project each element's dP/dF onto the positive semi-definite cone")
                                .fallback(newton.project_element_hessians),
                        })
                     .fallback(json::object()),
                 object("linear", "linear solver of each Newton iteration",
                        {
                            string("solver", "sparse Cholesky (CHOLMOD), GMRES or conjugate gradients")
                                .allowed({linear_solver_name(Kind::Cholmod), linear_solver_name(Kind::Gmres),
                                          linear_solver_name(Kind::ConjugateGradient)})
                                .fallback(linear_solver_name(linear.kind)),
                            number("tolerance", "relative residual at which iterative solvers stop")
                                .min(kMinTolerance)
                                .below(1)
                                .fallback(linear.tolerance),
                            integer("max_iterations", "iterative solvers' iteration limit")
                                .max(kMaxLinearIterations)
                                .min(1)
                                .fallback(linear.max_iterations),
                            integer("gmres_restart", "GMRES restart length").min(1).max(kMaxRestart).fallback(linear.gmres_restart),
                        })
                     .fallback(json::object()),
             })
      .fallback(json::object());
}

SchemaNode dynamics_schema() {
  const DynamicsConfig defaults;
  const auto& o = defaults.options;
  return object("dynamics",
                "time integration instead of load stepping (paper section 4): implicit Euler with inertia and "
                "viscosity (the seed's), quasistatic (viscosity, no inertia) or explicit central differences. "
                "Prescribed motions follow lambda = t / end_time; gravity and loads act in full from t = 0. The "
                "solver section's newton and linear settings apply to every implicit step.",
                {
                    string("integrator", "implicit-euler, quasistatic or explicit")
                        .allowed({"implicit-euler", "quasistatic", "explicit"})
                        .fallback("implicit-euler"),
                    number("end_time", "simulated time (time)").required().above(0).max(kMaxTime),
                    number("output_interval", "VTU/PVD output every this much simulated time (time)")
                        .required()
                        .above(0)
                        .max(kMaxTime),
                    number("time_step", "first step of the implicit integrators (time); default output_interval / 10")
                        .min(kMinTime)
                        .max(kMaxTime),
                    number("max_time_step", "upper bound of the adaptive step (time); default output_interval")
                        .min(kMinTime)
                        .max(kMaxTime),
                    number("min_time_step",
                           "a step halved below this fails the run (time); default 1e-6 of the first step")
                        .min(kMinTime)
                        .max(kMaxTime),
                    number("growth", "step growth after an easy step").min(1).max(kMaxGrowth).fallback(o.growth),
                    integer("easy_iterations", "Newton iterations at or below which a step counts as easy")
                        .max(kMaxIterations)
                        .min(0)
                        .fallback(o.easy_iterations),
                    string("mass", "lumped (rho V / 4 per node) or consistent mass matrix (implicit only)")
                        .allowed({"lumped", "consistent"})
                        .fallback("lumped"),
                    number("mass_damping", "Rayleigh viscosity D = mass_damping M + stiffness_damping K0: 1/time")
                        .max(kMaxPhysical)
                        .min(0)
                        .fallback(defaults.mass_damping),
                    number("stiffness_damping", "... and time (K0: elastic stiffness at rest)")
                        .max(kMaxPhysical)
                        .min(0)
                        .fallback(defaults.stiffness_damping),
                    number("explicit_safety", "explicit step as a fraction of the critical step 2 / omega_max")
                        .above(0)
                        .max(1)
                        .fallback(o.explicit_safety),
                });
}

SchemaNode output_schema() {
  const OutputConfig defaults;
  return object("output", "what is written",
                {
                    boolean("vtu", "write a .vtu per output step and a .pvd series").fallback(defaults.vtu),
                    integer("every", "write every n-th increment (the last one always)").min(1).max(kMaxIncrements).fallback(defaults.every),
                })
      .fallback(json::object());
}

Schema build_scene_schema() {
  Schema schema;
  schema.title = "sinew scene";
  schema.root = object("", "A scene: materials, bodies, boundary conditions, loads, solver and output settings",
                       {
                           string("name", "scene name, for logs and outputs").fallback(""),
                           string("description", "free text").free_text().fallback(""),
                           string("units",
                                  "the consistent unit system, e.g. \"mm, N, MPa, s\" (documentation only: sinew "
                                  "converts nothing)")
                               .required()
                               .non_empty(),
                           map("materials", "material name -> law and parameters", material_schema())
                               .fallback(json::object()),
                           array("bodies", "the solids", body_schema()).required().items(1),
                           array("boundary_conditions", "constraints on nodes", boundary_condition_schema())
                               .fallback(json::array()),
                           loads_schema(),
                           contact_schema(),
                           solver_schema(),
                           dynamics_schema(),
                           output_schema(),
                       });
  schema.definitions["node_selector"] = node_selector_definition();
  schema.definitions["motion"] = motion_definition();
  schema.definitions["amplitude"] = amplitude_definition();
  schema.definitions["shape"] = shape_definition();
  return schema;
}

}  // namespace

const Schema& scene_schema() {
  static const Schema schema = build_scene_schema();
  return schema;
}

json scene_json_schema() { return to_json_schema(scene_schema()); }

}  // namespace sinew::scene
