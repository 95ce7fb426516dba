#pragma once
/// @file stepper.hpp
/// One adaptive stepper for load steps and time steps (paper section 3.2, dissertation Fig. 12
/// loop 1, section 4.8): a parameter t goes from 0 to T through user-visible segments (load
/// increments, or output intervals of simulated time); each segment is reached in one or more
/// steps, each solved by Newton; a step that fails is halved, an easy one lets the next grow.
/// What differs between load and time stepping (the predictor, the inertia terms, the
/// wording of messages) is a StepScheme.

#include <functional>
#include <string>

#include "sinew/solver/newton_solver.hpp"

namespace sinew::solver {

/// One accepted (or attempted) step.
struct StepRecord {
  int segment = 0;          ///< user-visible increment or output interval this step belongs to (1-based)
  int step = 0;             ///< accepted steps so far, this one included
  double t = 0;             ///< parameter at the end of the step: load parameter lambda, or time
  double step_size = 0;     ///< its delta t
  int newton_iterations = 0;
  double residual = 0;      ///< final |g_q|
  double force_scale = 0;
  double energy = 0;
  int cuts = 0;             ///< step halvings so far (whole run)
  bool snap_through = false;  ///< attempted with the snap-through Newton budget
  int refinements = 0;      ///< re-solves of this step asked by the StepRefinement (0 without one)
  /// Energy the scheme's stabilization dissipated in this step (energy; 0 when not stabilized).
  double dissipated = 0;
};

/// What a step scheme carries from one accepted step to the next (StepScheme::memory).
struct SchemeMemory {
  /// Load stepping, two-point predictor: the accepted state before the last (x has 0 rows when
  /// there is none yet).
  fem::State previous;
  /// Load stepping, tangent predictor: dq/dlambda at the last accepted state (#q), or empty.
  VectorX tangent;
  /// Time stepping: nodal velocities of the last accepted state (#V x 3, length / time).
  NodalVectors velocity;
  /// Load stepping: the steps are stabilized (StepScheme::start_stabilizing was called).
  bool stabilized = false;
};

/// Counters of a run so far (StepperResult has the same).
struct StepCounts {
  int segments_completed = 0;
  int steps = 0;
  int newton_iterations = 0;
  int cuts = 0;
  int snap_throughs = 0;
  int refinements = 0;
  double min_step = 0, max_step = 0;  ///< of the accepted steps (t units)
  int stabilized_steps = 0;           ///< accepted steps with the scheme's stabilization
  double dissipated = 0;              ///< energy the stabilization dissipated in them
};

/// Where a run stands after an accepted step: what it takes to continue the run exactly as it
/// would have gone on (checkpoints and resume, docs/checkpoints.md).
struct StepperSnapshot {
  fem::State state;            ///< the last accepted state
  double t = 0;                ///< its parameter (lambda or time)
  double next_step = 0;        ///< size of the next attempt (t units), before bounds
  int segment = 1;             ///< segment of the last accepted step (1-based)
  bool segment_done = false;   ///< the step ended its segment (on_segment was called for it)
  StepRecord record;           ///< the last accepted step
  StepCounts counts;
  SchemeMemory scheme;
  /// Seconds spent per phase and linear-solver work by this process's run_stepper so far (not
  /// written to checkpoints: a stopped run's summary reports them up to its last accepted step).
  PhaseTimes times;
  LinearCounts linear;
};

struct StepperCallbacks {
  /// Every Newton iteration; `step` describes the step being attempted.
  std::function<void(const StepRecord& step, const IterationRecord& iteration)> on_iteration;
  /// Every accepted step (and the given start state as step 0 when the run does not solve
  /// for it): positions and nodal velocities (#V x 3; 0 rows in load stepping). Explicit
  /// integration calls it about 50 times per output interval (and at output times).
  std::function<void(const StepRecord& step, const fem::State& state, const NodalVectors& velocity)> on_step;
  /// The start state (segment 0) and the end of every segment.
  std::function<void(int segment, const StepRecord& step, const fem::State& state, const NodalVectors& velocity)>
      on_segment;
  /// A step failed and will be retried smaller.
  std::function<void(const StepRecord& step, const std::string& why)> on_cut;
  /// The step `step` failed at the smallest allowed size and the scheme stabilizes from here on
  /// (StepScheme::start_stabilizing); it is tried again at that size.
  std::function<void(const StepRecord& step, const std::string& why)> on_stabilize;
  /// After every accepted step, once on_step (and on_segment, when the step ended a segment)
  /// returned: where the run stands (not called by explicit integration).
  std::function<void(const StepperSnapshot& snapshot)> on_accepted;
};

/// What every run reports, load or time stepping.
struct StepperResult {
  bool success = false;
  std::string message;          ///< what was solved, or what failed, where, and what to try
  fem::State last_state;        ///< the last converged state
  NodalVectors last_velocity;   ///< #V x 3 (time stepping), 0 rows (load stepping)
  double t = 0;                 ///< parameter reached (lambda, or simulated time)
  int segments_completed = 0;   ///< increments or output intervals
  int steps = 0;
  int newton_iterations = 0;
  int cuts = 0;
  int snap_throughs = 0;        ///< steps solved with the snap-through budget
  int refinements = 0;          ///< re-solves asked by the StepRefinement in accepted steps
  double min_step = 0, max_step = 0;  ///< of the accepted steps (t units)
  int stabilized_steps = 0;     ///< accepted steps with the scheme's stabilization
  double dissipated = 0;        ///< energy the stabilization dissipated in them
  PhaseTimes times;
  LinearCounts linear;          ///< factorizations and linear iterations of this run
};

/// The counters of `result` (what a snapshot of it records).
StepCounts counts_of(const StepperResult& result);

struct StepperOptions {
  enum class Start {
    SolveEquilibrium,  ///< Newton at t = 0 first (a larger budget); no step-0 record
    GivenState         ///< the start state is reported as step 0 as it is
  };
  /// Growth after an easy step: always (load stepping), or only after a step that was not
  /// shortened to land on a segment end (time stepping).
  enum class Growth { AfterEasyStep, AfterEasyFullStep };
  double end = 1;             ///< T (> 0)
  /// Segment k ends at min(T, k segment_length); the last one exactly at T. Default: T.
  double segment_length = 0;
  double first_step = 1;      ///< first step size (t units)
  double max_step = 1;        ///< steps never grow beyond it
  double min_step = 1e-4;     ///< a cut below this fails the run (t units)
  double growth = 2;          ///< factor after an easy step
  int easy_iterations = 4;    ///< Newton iterations at or below which a step is easy
  /// A step that would end within this fraction of a segment of the segment's end ends there.
  double snap_to_segment_end = 0;
  /// After this many failed attempts in a row the next one gets `snap_through_iterations`
  /// Newton iterations (see LoadSteppingOptions); 0 disables it.
  int snap_through_after_cuts = 0;
  int snap_through_iterations = 200;
  /// The step size (t units) the stepper goes on with once the scheme stabilizes
  /// (StepScheme::start_stabilizing), or the failed size when that is larger.
  double stabilized_step = 0;
  Start start = Start::SolveEquilibrium;
  Growth growth_rule = Growth::AfterEasyStep;
  NewtonOptions newton;
  /// Continue from this snapshot (of a run of the same problem and options) instead of starting
  /// at t = 0: no start solve, no step-0 callbacks; counters go on from the snapshot's.
  const StepperSnapshot* resume = nullptr;
};

/// The part of a step that differs between load stepping and time stepping.
class StepScheme {
 public:
  virtual ~StepScheme() = default;
  /// The start state at t = 0 (sets the objective up for it).
  virtual fem::State start() = 0;
  /// The Newton starting point of a step from `current` (converged at t) to `t_new`, with the
  /// objective set up for t_new (load parameter, inertia centre, collision structures).
  virtual fem::State predict(const fem::State& current, double t, double t_new, NewtonSolver& newton) = 0;
  /// `current` converged at the end of a step of size h from `previous`.
  virtual void accept(const fem::State& previous, const fem::State& current, double h) = 0;
  /// What the next step needs of the steps before, at the last accepted state `current` (the
  /// tangent predictor computes its direction here, with `newton`'s last factorization, and
  /// uses it for the next step).
  virtual SchemeMemory memory(const fem::State& current, NewtonSolver& newton) = 0;
  /// Continue from `current` with what memory() returned (sets the objective up for it).
  virtual void restore(const fem::State& current, const SchemeMemory& memory) = 0;
  /// A step from `current` failed: undo what predict() set up for the objective.
  virtual void reject(const fem::State& current) = 0;
  /// A step failed at the smallest allowed size: switch a stabilization on for every later step
  /// and return true, or return false when there is none (or it is on already) and the run stops.
  virtual bool start_stabilizing() { return false; }
  /// Energy the stabilization dissipated in the step just accepted (0 when off). Its term in
  /// the objective, at the accepted state, is half of it (a quadratic viscous term).
  virtual double last_dissipation() const { return 0; }
  /// Nodal velocities of the last accepted state (#V x 3), or 0 rows.
  virtual const NodalVectors& velocity() const {
    static const NodalVectors none;
    return none;
  }
  /// Largest step from t not above `h` whose prescribed rotations stay within the per-step
  /// bound (prescribed_turn.hpp); below `smallest` means none.
  virtual double bound_step(double t, double h, double smallest) const = 0;
  /// Messages: why the run stopped.
  virtual std::string start_failed(const std::string& why) const = 0;
  virtual std::string turn_too_fast(double t, double smallest) const = 0;
  virtual std::string step_too_small(double t, double h, double smallest, const std::string& why) const = 0;
  virtual std::string solved(const StepperResult& result) const = 0;
};

/// An outer iteration around each step's Newton solve: augmented Lagrangian multiplier updates,
/// penalty growth between steps (contact_enforcement.hpp). The stepper calls refine() with each
/// converged state of a step; when it returns true the objective was changed and the step is
/// solved again from that state (the refinement bounds how often). When that re-solve fails, the
/// stepper goes back to the converged state and calls retry_softer(): a smaller change to solve
/// again, or none, and the step keeps the state it had converged to. A step whose first solve
/// fails is cut as any other, after reject().
class StepRefinement {
 public:
  virtual ~StepRefinement() = default;
  /// `converged` solves the current step: true when the objective was changed and the step
  /// must be solved again.
  virtual bool refine(const fem::State& converged) = 0;
  /// The solve after the last refine() failed. True after changing the objective by less than
  /// that refine() did (solve again from the state it was given); false when nothing smaller is
  /// left: the objective is back to the one that state solved, refine() returns false for the
  /// rest of the step, and the stepper accepts that state (a refreshed friction lag stays).
  virtual bool retry_softer() { return false; }
  /// The step was accepted at `state` (changes for the next step go here).
  virtual void accept(const fem::State& state) = 0;
  /// The step failed: restore the objective as it was at the last accept (or the start).
  virtual void reject() = 0;
};

/// Runs `scheme` from 0 to options.end with `newton`. Sets result.times.collision to the
/// objective's collision time over the run.
StepperResult run_stepper(NewtonSolver& newton, StepScheme& scheme, const StepperOptions& options,
                          const StepperCallbacks& callbacks = {}, StepRefinement* refinement = nullptr);

}  // namespace sinew::solver
