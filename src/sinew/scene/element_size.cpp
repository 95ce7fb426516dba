#include "sinew/scene/element_size.hpp"

#include <cmath>
#include <string>

#include "sinew/core/error.hpp"

namespace sinew::scene {

void set_element_size(SceneConfig& config, double element_size) {
  if (!std::isfinite(element_size) || element_size <= 0) {
    throw InputError("the element size must be a finite length > 0, not " + std::to_string(element_size));
  }
  for (BodyConfig& body : config.bodies) {
    if (body.mesh.surfaces) {
      surface::TetrahedralizeOptions& options = body.mesh.surfaces->options;
      const double ratio = element_size / options.element_size;
      options.element_size = element_size;
      options.facet_distance *= ratio;
      for (surface::SizeZone& zone : options.size_zones) zone.size *= ratio;
    } else if (body.mesh.file.empty()) {
      body.mesh.generate.element_size = element_size;
    }
  }
}

}  // namespace sinew::scene
