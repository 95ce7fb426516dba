#pragma once
/// @file scene_names.hpp
/// Names that become column names of a run's tables (app/run_output.cpp): every fixed or
/// prescribed condition, planar condition and rigid region ("<body>/<region>") gives reaction
/// columns "<name>.fx" ... "<name>.mz" in steps.csv, and with contact every pair of bodies
/// gives "contact.<a>.<b>.fx" ... (or "contact.<a>.<a>.force"). Two sources with one name
/// would give a table two columns of that name, so the run would stop at its first output.

#include <string>
#include <vector>

#include "sinew/scene/scene_config.hpp"

namespace sinew::scene {

/// The errors for names that clash, each "<path>: ..." naming both key paths:
/// - a boundary condition, force or rigid region with the name of another of a different
///   group (duplicates within boundary_conditions or within loads.forces are reported by the
///   reader);
/// - such a name equal to "contact.<a>.<b>" for bodies a before b, when the scene has contact;
/// - two pairs of bodies whose contact columns coincide (bodies "a.b", "c" and "a", "b.c").
/// Rigid regions are known from explicit `regions` keys, and for generated meshes from the
/// parts the "*" entry covers; a mesh file's regions covered by "*" are checked when the
/// problem is built (build_problem).
std::vector<std::string> output_name_clashes(const SceneConfig& config);

}  // namespace sinew::scene
