/// @file read_motion.cpp
/// Scene JSON -> amplitudes and rigid motions (docs/scene-reference.md, motions).

#include "sinew/scene/scene_reading.hpp"

namespace sinew::scene::reading {

fem::Amplitude read_amplitude(const json& j, const std::string& path, ReadErrors& errors) {
  fem::Amplitude amplitude;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const double lambda = j[i][0].get<double>();
    if (i > 0 && !(lambda > amplitude.points.back().first)) {
      errors.add(json_path_index(json_path_index(path, i), 0),
            "lambda must be strictly increasing, got " + format_number(lambda) + " after " +
                format_number(amplitude.points.back().first));
    }
    amplitude.points.emplace_back(lambda, j[i][1].get<double>());
  }
  return amplitude;
}

fem::RigidMotion read_motion(const json& j, const std::string& path, ReadErrors& errors) {
  fem::RigidMotion motion;
  motion.translation = to_vector3(j.at("translation"));
  if (j.contains("rotation")) {
    const json& rotation = j.at("rotation");
    motion.axis = to_vector3(rotation.at("axis"));
    motion.axis_point = to_vector3(rotation.at("point"));
    motion.angle = rotation.at("angle_deg").get<double>() * kRadiansPerDegree;
  }
  if (j.contains("amplitude")) motion.amplitude = read_amplitude(j.at("amplitude"), json_path_key(path, "amplitude"), errors);
  return motion;
}

}  // namespace sinew::scene::reading
