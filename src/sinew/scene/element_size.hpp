#pragma once
/// @file element_size.hpp
/// The same scene coarser or finer: one element size for every mesh sinew generates.

#include "sinew/scene/scene_config.hpp"

namespace sinew::scene {

/// Sets the element size (length) of every mesh the scene generates. Generated primitives take
/// it as their element_size; surface meshes take it as their element_size and scale their
/// facet_distance and size zones by the same ratio, so the grading keeps its shape. Bodies read
/// from mesh files are unchanged. Throws InputError unless element_size is finite and > 0.
void set_element_size(SceneConfig& config, double element_size);

}  // namespace sinew::scene
