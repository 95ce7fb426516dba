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

namespace {

/// The keyframes of a motion, keyed by load parameter or (dynamics, `end_time` > 0) by time.
std::vector<fem::Keyframe> read_keyframes(const json& keys, const std::string& path, double end_time,
                                          ReadErrors& errors) {
  std::vector<fem::Keyframe> keyframes;
  bool by_time = false;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const json& key = keys[i];
    const std::string key_path = json_path_index(path, i);
    const bool has_lambda = key.contains("lambda"), has_time = key.contains("time");
    fem::Keyframe frame;
    if (has_lambda == has_time) {
      errors.add(key_path, "give the keyframe's place as exactly one of \"lambda\" (load parameter) or \"time\"");
      continue;
    }
    if (i == 0) by_time = has_time;
    if (has_time != by_time) {
      errors.add(key_path, "keyframes of one motion are keyed all by \"lambda\" or all by \"time\", not both");
      continue;
    }
    if (has_time) {
      const double time = key.at("time").get<double>();
      if (!(end_time > 0)) {
        errors.add(json_path_key(key_path, "time"),
                   "a keyframe keyed by time needs a dynamic analysis (a \"dynamics\" section); a static one is "
                   "keyed by \"lambda\"");
        continue;
      }
      frame.lambda = time / end_time;  // prescribed motions follow lambda = t / end_time
    } else {
      frame.lambda = key.at("lambda").get<double>();
    }
    const double place = has_time ? key.at("time").get<double>() : frame.lambda;
    if (!keyframes.empty() && !(frame.lambda > keyframes.back().lambda)) {
      errors.add(json_path_key(key_path, has_time ? "time" : "lambda"),
                 "keyframes must be strictly increasing, got " + format_number(place) + " after " +
                     format_number(has_time ? keyframes.back().lambda * end_time : keyframes.back().lambda));
    }
    frame.translation = to_vector3(key.at("translation"));
    if (key.contains("rotation")) {
      const json& rotation = key.at("rotation");
      frame.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(rotation.at("angle_deg").get<double>() * kRadiansPerDegree,
                                                            to_vector3(rotation.at("axis")).normalized()));
    }
    keyframes.push_back(frame);
  }
  return keyframes;
}

}  // namespace

fem::RigidMotion read_motion(const json& j, const std::string& path, ReadErrors& errors, double end_time) {
  fem::RigidMotion motion;
  if (j.contains("keyframes")) {
    const bool other = !to_vector3(j.at("translation")).isZero(0) || j.contains("rotation") || j.contains("amplitude");
    if (other)
      errors.add(json_path_key(path, "keyframes"),
                 "keyframes replace \"translation\", \"rotation\" and \"amplitude\": give either the keyframes "
                 "or those");
    motion.keyframes = read_keyframes(j.at("keyframes"), json_path_key(path, "keyframes"), end_time, errors);
    motion.pivot = to_vector3(j.at("pivot"));
    return motion;
  }
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
