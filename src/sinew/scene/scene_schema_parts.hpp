#pragma once
/// @file scene_schema_parts.hpp
/// The parts the scene schema (scene_schema.cpp) is assembled from, one file each:
/// shared definitions (scene_schema_definitions.cpp), materials (scene_schema_material.cpp),
/// bodies (scene_schema_body.cpp), boundary conditions and loads (scene_schema_loads.cpp),
/// contact (scene_schema_contact.cpp), and the solver, dynamics and output settings
/// (scene_schema_solver.cpp). Internal to the scene module.

#include "sinew/scene/schema.hpp"

namespace sinew::scene::schema_parts {

// Definitions, referred to by name (SchemaType::Ref).
SchemaNode amplitude_definition();
SchemaNode motion_definition();
SchemaNode node_selector_definition();
SchemaNode shape_definition();
SchemaNode solid_definition();

// Top-level keys.
SchemaNode material_schema();            ///< a value of "materials"
SchemaNode body_schema();                ///< an element of "bodies"
SchemaNode boundary_condition_schema();  ///< an element of "boundary_conditions"
SchemaNode loads_schema();               ///< "loads"
SchemaNode contact_schema();             ///< "contact"
SchemaNode solver_schema();              ///< "solver"
SchemaNode dynamics_schema();            ///< "dynamics"
SchemaNode output_schema();              ///< "output"

}  // namespace sinew::scene::schema_parts
