#pragma once
/// @file stage_start.hpp
/// Sequential stages (docs/stages.md): a model whose motions start from the final state of an
/// earlier run of the same meshes, as the dissertation (section 5.4.5) split an analysis session
/// into sequential runs.

#include <string>

#include "sinew/model/model.hpp"

namespace sinew::model {

/// Makes the final state of the finished run whose output directory is `directory` the state
/// `model` starts from (fem::DofMap::set_start): its node positions and rigid-body poses, and,
/// when both runs are dynamic and this one has inertia, its nodal velocities (Model::start_velocity).
/// The rest state, the material depth and the elements' reference stay those of the meshes.
/// Throws InputError, naming `directory`, when there is no checkpoint there, the run did not
/// finish, its meshes are not this model's, or its rigid bodies do not fit.
void start_from_run(Model& model, const std::string& directory);

}  // namespace sinew::model
