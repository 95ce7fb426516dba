#include "sinew/model/checkpoint.hpp"

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "sinew/core/error.hpp"
#include "sinew/io/atomic_file.hpp"

namespace sinew::model {

namespace {

using nlohmann::json;

constexpr const char* kFormat = "sinew-checkpoint";
constexpr int kVersion = 1;

/// A checkpoint that does not parse as one: its reading stops with this.
struct Malformed {
  std::string what;
};

/// A dense matrix as {rows, cols, data: the column-major doubles as raw bytes}.
json matrix_json(const MatrixX& m) {
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(m.size()) * sizeof(double));
  if (!bytes.empty()) std::memcpy(bytes.data(), m.data(), bytes.size());
  return {{"rows", m.rows()}, {"cols", m.cols()}, {"data", json::binary(std::move(bytes))}};
}

const json& field(const json& j, const char* key) {
  if (!j.is_object() || !j.contains(key)) throw Malformed{fmt::format("no \"{}\"", key)};
  return j.at(key);
}

MatrixX matrix_from(const json& j, const char* key) {
  const json& m = field(j, key);
  const auto rows = field(m, "rows").get<long long>();
  const auto cols = field(m, "cols").get<long long>();
  const json& data = field(m, "data");
  // The sizes are checked against the bytes there before they are multiplied (no overflow, no
  // allocation beyond what the file holds).
  const auto doubles = data.is_binary() ? static_cast<long long>(data.get_binary().size() / sizeof(double)) : -1;
  if (rows < 0 || cols < 0 || doubles < 0 || data.get_binary().size() % sizeof(double) != 0 ||
      (cols > 0 && rows > doubles / cols) || rows * cols != doubles)
    throw Malformed{fmt::format("\"{}\" is not a {} x {} matrix", key, rows, cols)};
  MatrixX out(rows, cols);
  if (out.size() > 0) std::memcpy(out.data(), data.get_binary().data(), data.get_binary().size());
  return out;
}

json state_json(const fem::State& s) {
  json rigid = json::array();
  for (const fem::RigidPose& pose : s.rigid) rigid.push_back({{"R", matrix_json(pose.R)}, {"t", matrix_json(pose.t)}});
  return {{"x", matrix_json(s.x)}, {"rigid", rigid}, {"lambda", s.lambda}};
}

fem::State state_from(const json& j) {
  fem::State s;
  s.x = matrix_from(j, "x");
  if (s.x.rows() > 0 && s.x.cols() != 3) throw Malformed{"positions are not #V x 3"};
  for (const json& pose : field(j, "rigid")) {
    fem::RigidPose p;
    const MatrixX R = matrix_from(pose, "R"), t = matrix_from(pose, "t");
    if (R.rows() != 3 || R.cols() != 3 || t.rows() != 3 || t.cols() != 1) throw Malformed{"a rigid pose is not 3 x 3, 3"};
    p.R = R;
    p.t = t;
    s.rigid.push_back(p);
  }
  s.lambda = field(j, "lambda").get<double>();
  return s;
}

json record_json(const solver::StepRecord& r) {
  return {{"segment", r.segment},     {"step", r.step},   {"t", r.t},
          {"step_size", r.step_size}, {"newton_iterations", r.newton_iterations},
          {"residual", r.residual},   {"force_scale", r.force_scale},
          {"energy", r.energy},       {"cuts", r.cuts},   {"snap_through", r.snap_through},
          {"refinements", r.refinements}, {"dissipated", r.dissipated}};
}

/// A number written by later versions of sinew, or `absent` in a checkpoint from before it.
template <typename T>
T optional_field(const json& j, const char* name, T absent) {
  return j.contains(name) ? j.at(name).get<T>() : absent;
}

solver::StepRecord record_from(const json& j) {
  solver::StepRecord r;
  r.segment = field(j, "segment").get<int>();
  r.step = field(j, "step").get<int>();
  r.t = field(j, "t").get<double>();
  r.step_size = field(j, "step_size").get<double>();
  r.newton_iterations = field(j, "newton_iterations").get<int>();
  r.residual = field(j, "residual").get<double>();
  r.force_scale = field(j, "force_scale").get<double>();
  r.energy = field(j, "energy").get<double>();
  r.cuts = field(j, "cuts").get<int>();
  r.snap_through = field(j, "snap_through").get<bool>();
  r.refinements = field(j, "refinements").get<int>();
  r.dissipated = optional_field(j, "dissipated", 0.0);  // before stabilization: none
  return r;
}

json counts_json(const solver::StepCounts& c) {
  return {{"segments_completed", c.segments_completed},
          {"steps", c.steps},
          {"newton_iterations", c.newton_iterations},
          {"cuts", c.cuts},
          {"snap_throughs", c.snap_throughs},
          {"refinements", c.refinements},
          {"min_step", c.min_step},
          {"max_step", c.max_step},
          {"stabilized_steps", c.stabilized_steps},
          {"dissipated", c.dissipated}};
}

solver::StepCounts counts_from(const json& j) {
  solver::StepCounts c;
  c.segments_completed = field(j, "segments_completed").get<int>();
  c.steps = field(j, "steps").get<int>();
  c.newton_iterations = field(j, "newton_iterations").get<int>();
  c.cuts = field(j, "cuts").get<int>();
  c.snap_throughs = field(j, "snap_throughs").get<int>();
  c.refinements = field(j, "refinements").get<int>();
  c.min_step = field(j, "min_step").get<double>();
  c.max_step = field(j, "max_step").get<double>();
  c.stabilized_steps = optional_field(j, "stabilized_steps", 0);
  c.dissipated = optional_field(j, "dissipated", 0.0);
  return c;
}

json checkpoint_json(const Checkpoint& c) {
  const solver::StepperSnapshot& s = c.snapshot.stepper;
  json series = json::array();
  for (const auto& [time, file] : c.series) series.push_back({{"time", time}, {"file", file}});
  return {{"format", kFormat},
          {"version", kVersion},
          {"fingerprint", c.fingerprint},
          {"mesh_fingerprint", c.mesh_fingerprint},
          {"finished", c.finished},
          {"stepper",
           {{"state", state_json(s.state)},
            {"t", s.t},
            {"next_step", s.next_step},
            {"segment", s.segment},
            {"segment_done", s.segment_done},
            {"record", record_json(s.record)},
            {"counts", counts_json(s.counts)},
            {"scheme",
             {{"previous", state_json(s.scheme.previous)},
              {"tangent", matrix_json(s.scheme.tangent)},
              {"velocity", matrix_json(s.scheme.velocity)},
              {"stabilized", s.scheme.stabilized}}}}},
          {"contact_penalty", matrix_json(c.snapshot.contact_penalty)},
          {"contact_pressure", matrix_json(c.snapshot.contact_pressure)},
          {"counters", c.counters},
          {"series", series}};
}

Checkpoint checkpoint_from(const json& j) {
  Checkpoint c;
  c.fingerprint = field(j, "fingerprint").get<std::uint64_t>();
  // Absent from the checkpoints of sinew before sequential stages: those can still resume.
  if (j.contains("mesh_fingerprint")) c.mesh_fingerprint = j.at("mesh_fingerprint").get<std::uint64_t>();
  if (j.contains("finished")) c.finished = j.at("finished").get<bool>();
  const json& s = field(j, "stepper");
  solver::StepperSnapshot& snapshot = c.snapshot.stepper;
  snapshot.state = state_from(field(s, "state"));
  snapshot.t = field(s, "t").get<double>();
  snapshot.next_step = field(s, "next_step").get<double>();
  snapshot.segment = field(s, "segment").get<int>();
  snapshot.segment_done = field(s, "segment_done").get<bool>();
  snapshot.record = record_from(field(s, "record"));
  snapshot.counts = counts_from(field(s, "counts"));
  const json& scheme = field(s, "scheme");
  snapshot.scheme.previous = state_from(field(scheme, "previous"));
  const MatrixX tangent = matrix_from(scheme, "tangent");
  if (tangent.cols() > 1) throw Malformed{"the predictor's tangent is not a vector"};
  snapshot.scheme.tangent = tangent.reshaped();
  snapshot.scheme.velocity = matrix_from(scheme, "velocity");
  snapshot.scheme.stabilized = optional_field(scheme, "stabilized", false);
  c.snapshot.contact_penalty = matrix_from(j, "contact_penalty");
  const MatrixX pressure = matrix_from(j, "contact_pressure");
  if (pressure.cols() > 1) throw Malformed{"the contact pressures are not a vector"};
  c.snapshot.contact_pressure = pressure.reshaped();
  c.counters = field(j, "counters").get<std::map<std::string, long long>>();
  for (const json& entry : field(j, "series"))
    c.series.emplace_back(field(entry, "time").get<double>(), field(entry, "file").get<std::string>());
  if (!(snapshot.next_step > 0) || snapshot.segment < 1 || snapshot.counts.steps < 1)
    throw Malformed{"its step counters are out of range"};
  return c;
}

/// FNV-1a over bytes.
struct Fnv1a {
  std::uint64_t hash = 14695981039346656037ull;
  void add(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
      hash ^= bytes[i];
      hash *= 1099511628211ull;
    }
  }
  template <typename Matrix>
  void add_matrix(const Matrix& m) {
    const long long shape[2] = {static_cast<long long>(m.rows()), static_cast<long long>(m.cols())};
    add(shape, sizeof(shape));
    add(m.data(), static_cast<std::size_t>(m.size()) * sizeof(typename Matrix::Scalar));
  }
};

/// About the size of `c` in CBOR: its matrices' bytes and room for the rest.
std::size_t expected_cbor_bytes(const Checkpoint& c) {
  const solver::StepperSnapshot& s = c.snapshot.stepper;
  const auto matrices = static_cast<std::size_t>(s.state.x.size() + s.scheme.previous.x.size() +
                                                s.scheme.tangent.size() + s.scheme.velocity.size() +
                                                c.snapshot.contact_penalty.size() + c.snapshot.contact_pressure.size());
  const std::size_t doubles = matrices + 12 * (s.state.rigid.size() + s.scheme.previous.rigid.size());
  return sizeof(double) * doubles + 128 * (c.series.size() + s.state.rigid.size() + c.counters.size()) + 4096;
}

}  // namespace

RunSnapshot take_snapshot(const Model& model, const solver::StepperSnapshot& stepper) {
  RunSnapshot snapshot;
  snapshot.stepper = stepper;
  if (model.contact) {
    snapshot.contact_penalty = model.contact->geometry().penalty;
    snapshot.contact_pressure = model.contact->pressure();
  }
  return snapshot;
}

void write_checkpoint(const std::string& path, const Checkpoint& checkpoint) {
  // A rank that writes no files (MPI ranks other than 0) encodes nothing: the JSON and the bytes
  // are two more copies of the whole snapshot (docs/mpi.md).
  if (!io::files_written()) return;
  std::vector<std::uint8_t> bytes;
  bytes.reserve(expected_cbor_bytes(checkpoint));  // no doubling growth of the largest buffer
  json::to_cbor(checkpoint_json(checkpoint), bytes);
  io::write_file_atomically(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

Checkpoint read_checkpoint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("no checkpoint at \"{}\": {}", path, std::strerror(errno)));
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const std::string prefix = fmt::format("\"{}\" is not a usable sinew checkpoint", path);
  json j;
  try {
    j = json::from_cbor(bytes);
  } catch (const json::exception& e) {
    throw InputError(fmt::format("{} (it does not parse: {}); the run cannot resume from it", prefix, e.what()));
  }
  if (!j.is_object() || !j.contains("format") || j["format"] != kFormat)
    throw InputError(fmt::format("{}: it was not written by sinew", prefix));
  if (!j.contains("version") || j["version"] != kVersion)
    throw InputError(fmt::format("{}: it has format version {}, this sinew reads version {}; run the scene again "
                                 "without --resume",
                                 prefix, j.contains("version") ? j["version"].dump() : "(none)", kVersion));
  try {
    return checkpoint_from(j);
  } catch (const Malformed& e) {
    throw InputError(fmt::format("{}: it is damaged ({})", prefix, e.what));
  } catch (const json::exception& e) {
    throw InputError(fmt::format("{}: it is damaged ({})", prefix, e.what()));
  }
}

std::uint64_t model_fingerprint(const Model& model, std::string_view scene_text) {
  Fnv1a h;
  h.add(scene_text.data(), scene_text.size());
  const mesh::TetMesh& mesh = model.problem->mesh;
  h.add_matrix(mesh.rest);
  h.add_matrix(mesh.tets);
  h.add_matrix(mesh.region);
  const long long counts[2] = {static_cast<long long>(model.dofs->num_dofs()),
                               static_cast<long long>(model.problem->rigid_bodies.size())};
  h.add(counts, sizeof(counts));
  // A later stage is another run when the state it starts from changed.
  if (model.dofs->has_start()) {
    const fem::State start = model.dofs->initial_state(0.0);
    h.add_matrix(start.x);
    if (model.start_velocity.rows() > 0) h.add_matrix(model.start_velocity);
  }
  return h.hash;
}

std::uint64_t mesh_fingerprint(const Model& model) {
  Fnv1a h;
  const mesh::TetMesh& mesh = model.problem->mesh;
  h.add_matrix(mesh.rest);
  h.add_matrix(mesh.tets);
  return h.hash;
}

void check_snapshot_fits(const Model& model, const RunSnapshot& snapshot, const std::string& source) {
  const solver::StepperSnapshot& s = snapshot.stepper;
  const Index nodes = model.problem->mesh.num_nodes();
  auto refuse = [&](const std::string& what) {
    throw InputError(fmt::format("{} does not fit this scene ({}): run it again without --resume", source, what));
  };
  if (s.state.x.rows() != nodes) refuse(fmt::format("{} nodes, the scene has {}", s.state.x.rows(), nodes));
  if (s.state.rigid.size() != model.problem->rigid_bodies.size()) refuse("another number of rigid bodies");
  const auto& previous = s.scheme.previous;
  if (previous.x.rows() != 0 && (previous.x.rows() != nodes || previous.rigid.size() != s.state.rigid.size()))
    refuse("the predictor's previous state has another size");
  if (s.scheme.tangent.size() != 0 && s.scheme.tangent.size() != model.dofs->num_dofs())
    refuse("the predictor's tangent has another number of unknowns");
  if (s.scheme.velocity.rows() != 0 && (s.scheme.velocity.rows() != nodes || s.scheme.velocity.cols() != 3))
    refuse("the velocities have another size");
  if (model.is_dynamic() != (s.scheme.velocity.rows() != 0)) refuse("a static and a dynamic analysis");
  const Index bodies = model.contact ? model.contact->num_bodies() : 0;
  if (snapshot.contact_penalty.rows() != bodies || snapshot.contact_penalty.cols() != bodies)
    refuse("another number of contact bodies");
  if (snapshot.contact_pressure.size() != 0 && snapshot.contact_pressure.size() != nodes)
    refuse("another number of contact pressures");
  if (!s.state.x.allFinite() || !std::isfinite(s.t)) refuse("positions that are not finite");
}

}  // namespace sinew::model
