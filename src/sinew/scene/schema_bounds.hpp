#pragma once
/// @file schema_bounds.hpp
/// The bounds of the scene schema's numbers. Every number is bounded, in the scene's own units,
/// so that the products the solver forms (modulus x strain, penalty x depth^2 x area, density x
/// gravity x volume, ...) stay finite and Gmsh's geometry well conditioned; real scenes lie
/// orders of magnitude inside (docs/scene-reference.md, Conventions: Bounds).

namespace sinew::scene::schema_bounds {

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

}  // namespace sinew::scene::schema_bounds
