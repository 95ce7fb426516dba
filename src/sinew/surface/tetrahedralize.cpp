/// @file tetrahedralize.cpp
/// CGAL Mesh_3 on a labelled domain: the label of a point is 1 + the index of the first part
/// whose solid contains it, 0 outside every part.

#include "sinew/surface/tetrahedralize.hpp"

#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Random.h>
#include <CGAL/make_mesh_3.h>
#include <CGAL/refine_mesh_3.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>

#include <fmt/format.h>

#include "sinew/core/error.hpp"
#include "sinew/core/stopwatch.hpp"
#include "sinew/surface/cgal_surface.hpp"
#include "sinew/surface/surface_checks.hpp"

namespace sinew::surface {

namespace {

using Kernel = cgal::Kernel;
using Domain = CGAL::Labeled_mesh_domain_3<Kernel>;
using Triangulation = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using Complex = CGAL::Mesh_complex_3_in_triangulation_3<Triangulation>;
using Criteria = CGAL::Mesh_criteria_3<Triangulation>;

/// The size field of TetrahedralizeOptions, as Mesh_3 asks for it.
struct SizeField {
  const TetrahedralizeOptions* options;
  const SurfaceLibrary* library;
  double operator()(const Kernel::Point_3& p, int /*dimension*/, const Domain::Index& /*index*/) const {
    double size = options->element_size;
    const Vector3 x = cgal::to_vector(p);
    for (const SizeZone& zone : options->size_zones) {
      if (zone.size >= size) continue;
      const double reach = (size - zone.size) / std::max(zone.grading, 1e-12);
      double distance = std::numeric_limits<double>::infinity();
      for (const std::string& name : zone.surfaces) {
        const ClosedSurface& surface = library->at(name);
        const Bounds b = surface.bounds();
        const Vector3 gap = (b.min - x).cwiseMax(x - b.max).cwiseMax(Vector3::Zero());
        if (gap.norm() > reach) continue;  // too far to matter
        distance = std::min(distance, std::abs(surface.signed_distance(x)));
      }
      if (zone.capsule) distance = std::min(distance, capsule_distance(*zone.capsule, x));
      if (std::isfinite(distance)) size = std::min(size, zone.size + zone.grading * distance);
    }
    return size;
  }
};

Bounds domain_bounds(const std::vector<SolidPart>& parts, const SurfaceLibrary& library, const std::string& what) {
  Bounds bounds;
  for (const SolidPart& part : parts) {
    const Bounds b = solid_bounds(part.solid, library);
    if (!b.min.allFinite() || !b.max.allFinite()) {
      throw InputError(what + ": part \"" + part.region + "\" is unbounded (a half-space needs to be intersected with a bounded solid)");
    }
    bounds.extend(b);
  }
  return bounds;
}

/// Tets of the complex as a TetMesh, regions in part order, positively oriented.
mesh::TetMesh extract_mesh(const Complex& complex, const std::vector<SolidPart>& parts) {
  mesh::TetMesh result;
  for (const SolidPart& part : parts) result.region_names.push_back(part.region);
  std::map<Triangulation::Vertex_handle, Index> node;
  std::vector<Vector3> points;
  std::vector<std::array<Index, 4>> tets;
  std::vector<Index> regions;
  for (auto cell = complex.cells_in_complex_begin(); cell != complex.cells_in_complex_end(); ++cell) {
    std::array<Index, 4> tet{};
    for (int k = 0; k < 4; ++k) {
      const auto vertex = cell->vertex(k);
      auto [it, added] = node.try_emplace(vertex, static_cast<Index>(points.size()));
      if (added) points.push_back(cgal::to_vector(vertex->point().point()));
      tet[static_cast<std::size_t>(k)] = it->second;
    }
    tets.push_back(tet);
    regions.push_back(static_cast<Index>(complex.subdomain_index(cell)) - 1);
  }
  result.rest.resize(static_cast<Index>(points.size()), 3);
  for (std::size_t v = 0; v < points.size(); ++v) result.rest.row(static_cast<Index>(v)) = points[v].transpose();
  result.tets.resize(static_cast<Index>(tets.size()), 4);
  result.region.resize(static_cast<Index>(tets.size()));
  for (std::size_t t = 0; t < tets.size(); ++t) {
    for (int k = 0; k < 4; ++k) result.tets(static_cast<Index>(t), k) = tets[t][static_cast<std::size_t>(k)];
    result.region(static_cast<Index>(t)) = regions[t];
    if (mesh::signed_volume(result.rest, result.tets, static_cast<Index>(t)) < 0) {
      std::swap(result.tets(static_cast<Index>(t), 2), result.tets(static_cast<Index>(t), 3));
    }
  }
  return result;
}

/// Seeds the triangulation with points on every interface between two labels: Mesh_3's own
/// initialisation shoots random rays from the domain's centre and misses small parts (a patella
/// in a leg). A grid of spacing `spacing` over `bounds` is labelled; every grid edge whose ends
/// differ is cut by the domain's exact boundary search, and up to `per_interface` of those
/// points per pair of labels (spread over the grid, none closer than spacing / 2 to another) are
/// inserted on the surface.
void seed_interfaces(Complex& complex, const Domain& domain, const std::function<int(const Kernel::Point_3&)>& label,
                     const Bounds& bounds, double spacing, std::size_t per_interface) {
  const Vector3 extent = bounds.max - bounds.min;
  Eigen::Vector3i count;
  for (int d = 0; d < 3; ++d) count[d] = std::max(2, static_cast<int>(std::ceil(extent[d] / spacing)) + 1);
  const auto at = [&](int i, int j, int k) {
    return Vector3(bounds.min.x() + extent.x() * i / (count[0] - 1), bounds.min.y() + extent.y() * j / (count[1] - 1),
                   bounds.min.z() + extent.z() * k / (count[2] - 1));
  };
  std::vector<int> labels(static_cast<std::size_t>(count[0]) * count[1] * count[2]);
  const auto id = [&](int i, int j, int k) { return (static_cast<std::size_t>(k) * count[1] + j) * count[0] + i; };
  for (int k = 0; k < count[2]; ++k) {
    for (int j = 0; j < count[1]; ++j) {
      for (int i = 0; i < count[0]; ++i) labels[id(i, j, k)] = label(cgal::to_point(at(i, j, k)));
    }
  }
  std::map<std::pair<int, int>, std::vector<std::pair<Vector3, Vector3>>> crossings;
  for (int k = 0; k < count[2]; ++k) {
    for (int j = 0; j < count[1]; ++j) {
      for (int i = 0; i < count[0]; ++i) {
        const int here = labels[id(i, j, k)];
        const std::array<std::array<int, 3>, 3> next{{{i + 1, j, k}, {i, j + 1, k}, {i, j, k + 1}}};
        for (const auto& n : next) {
          if (n[0] >= count[0] || n[1] >= count[1] || n[2] >= count[2]) continue;
          const int there = labels[id(n[0], n[1], n[2])];
          if (there != here) crossings[{std::min(here, there), std::max(here, there)}].emplace_back(at(i, j, k), at(n[0], n[1], n[2]));
        }
      }
    }
  }
  Triangulation& triangulation = complex.triangulation();
  const auto intersect = domain.construct_intersection_object();
  // A grid point on an interface is the crossing of all its edges: keep one seed of such a
  // cluster (nearly coincident seeds make Mesh_3 refine to zero-volume tets around them).
  std::vector<Vector3> seeded;
  const double min_gap = 0.5 * spacing;
  for (const auto& [pair, segments] : crossings) {
    const std::size_t stride = std::max<std::size_t>(1, segments.size() / per_interface);
    for (std::size_t s = 0; s < segments.size(); s += stride) {
      const auto hit = intersect(Kernel::Segment_3(cgal::to_point(segments[s].first), cgal::to_point(segments[s].second)));
      if (std::get<2>(hit) == 0) continue;
      const Vector3 x = cgal::to_vector(std::get<0>(hit));
      if (std::any_of(seeded.begin(), seeded.end(), [&](const Vector3& y) { return (x - y).norm() < min_gap; })) continue;
      seeded.push_back(x);
      const auto vertex = triangulation.insert(Triangulation::Weighted_point(std::get<0>(hit)));
      if (vertex == Triangulation::Vertex_handle()) continue;
      complex.set_dimension(vertex, 2);
      complex.set_index(vertex, std::get<1>(hit));
    }
  }
}

/// The face set "<region>.surface" of every region: the boundary of its tets.
void add_region_surfaces(mesh::TetMesh& result) {
  for (Index r = 0; r < static_cast<Index>(result.region_names.size()); ++r) {
    std::vector<Index> rows;
    for (Index t = 0; t < result.num_tets(); ++t) {
      if (result.region(t) == r) rows.push_back(t);
    }
    Tets region_tets(static_cast<Index>(rows.size()), 4);
    for (std::size_t i = 0; i < rows.size(); ++i) region_tets.row(static_cast<Index>(i)) = result.tets.row(rows[i]);
    const std::string name = result.region_names[static_cast<std::size_t>(r)] + ".surface";
    result.face_sets[name] = mesh::boundary_triangles(region_tets);
    std::vector<Index> nodes(result.face_sets[name].data(), result.face_sets[name].data() + result.face_sets[name].size());
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    result.node_sets[name] = std::move(nodes);
  }
}

}  // namespace

double capsule_distance(const ZoneCapsule& capsule, const Vector3& x) {
  return std::max(0.0, segment_distance(capsule.a, capsule.b, x) - capsule.radius);
}

double estimated_tets(const std::vector<SolidPart>& parts, const SurfaceLibrary& library,
                      const TetrahedralizeOptions& options) {
  constexpr double kTetsPerEdgeCubed = 8.48528137423857;  // 6 sqrt(2): regular tets of edge h per h^3
  const Bounds bounds = domain_bounds(parts, library, options.what);
  const Vector3 extent = bounds.max - bounds.min;
  double tets = kTetsPerEdgeCubed * extent.prod() / std::pow(options.element_size, 3);
  for (const SizeZone& zone : options.size_zones) {
    if (!(zone.size < options.element_size)) continue;
    for (const std::string& name : zone.surfaces) {
      if (library.count(name) == 0) continue;
      tets += kTetsPerEdgeCubed * surface_area(library.at(name).mesh()) / (zone.size * zone.size);
    }
    if (zone.capsule) {
      const double r = zone.capsule->radius, length = (zone.capsule->b - zone.capsule->a).norm();
      const double volume = std::numbers::pi * r * r * length + 4.0 / 3.0 * std::numbers::pi * r * r * r;
      tets += kTetsPerEdgeCubed * volume / std::pow(zone.size, 3);
    }
  }
  return tets;
}

mesh::TetMesh tetrahedralize(const std::vector<SolidPart>& parts, const SurfaceLibrary& library,
                             const TetrahedralizeOptions& options, TetrahedralizeReport* report) {
  const auto start = std::chrono::steady_clock::now();
  const std::string& what = options.what;
  if (parts.empty()) throw InputError(what + ": no parts to mesh");
  if (!(options.element_size > 0)) throw InputError(what + ": element_size must be > 0");
  for (const SolidPart& part : parts) check_solid(part.solid, library, what + ": part \"" + part.region + "\"");
  const Bounds bounds = domain_bounds(parts, library, what);
  for (const SizeZone& zone : options.size_zones) {
    for (const std::string& name : zone.surfaces) {
      if (library.count(name) == 0) throw InputError(what + ": a size zone names an unknown surface \"" + name + "\"");
    }
    if (zone.surfaces.empty() && !zone.capsule) throw InputError(what + ": a size zone needs surfaces or a capsule");
    if (zone.capsule && !(zone.capsule->radius > 0 && std::isfinite(zone.capsule->radius)))
      throw InputError(fmt::format("{}: a size zone's capsule needs a radius > 0, not {}", what, zone.capsule->radius));
  }
  if (options.max_tets > 0) {
    const double estimate = estimated_tets(parts, library, options);
    if (estimate > options.max_tets) {
      throw InputError(fmt::format("{}: an estimated {:.3g} tets at element_size {:g} exceed the limit of {:.3g} tets "
                                   "(raise it with --max-tets); or raise element_size",
                                   what, estimate, options.element_size, options.max_tets));
    }
  }
  const Vector3 pad = Vector3::Constant(options.element_size);
  const CGAL::Bbox_3 box(bounds.min.x() - pad.x(), bounds.min.y() - pad.y(), bounds.min.z() - pad.z(),
                         bounds.max.x() + pad.x(), bounds.max.y() + pad.y(), bounds.max.z() + pad.z());
  const std::function<int(const Kernel::Point_3&)> label = [&](const Kernel::Point_3& p) {
    const Vector3 x = cgal::to_vector(p);
    for (std::size_t i = 0; i < parts.size(); ++i) {
      if (solid_contains(parts[i].solid, library, x)) return static_cast<int>(i) + 1;
    }
    return 0;
  };
  CGAL::Random random(20011);  // fixed: the same scene gives the same mesh
  // Boundary points are found by bisection to 1e-6 of the box's diagonal (0.5 um on a 0.5 m leg).
  const Domain domain(label, box, 1e-6, CGAL::Null_subdomain_index(), &random);
  const SizeField size{&options, &library};
  const double facet_distance = options.facet_distance > 0 ? options.facet_distance : options.element_size / 20.0;
  const Criteria criteria(CGAL::parameters::facet_angle = 25, CGAL::parameters::facet_size = size,
                          CGAL::parameters::facet_distance = facet_distance,
                          CGAL::parameters::cell_radius_edge_ratio = 3, CGAL::parameters::cell_size = size);
  CGAL::get_default_random() = CGAL::Random(20011);
  Complex complex;
  const double extent = (bounds.max - bounds.min).maxCoeff();
  const double spacing = std::max(0.5 * options.element_size, extent / 160.0);
  // Over the padded box, so that the grid also has points outside every part and the outer
  // boundary is seeded (a part that fills its bounds, such as a box, has no other interface).
  Bounds padded;
  padded.extend(bounds.min - pad);
  padded.extend(bounds.max + pad);
  seed_interfaces(complex, domain, label, padded, spacing, 64);
  // Without a time limit of their own, perturb and exude stop after as much wall time as the
  // refinement took: the mesh would depend on the machine's load. 0 = until they are done.
  CGAL::refine_mesh_3(complex, domain, criteria, CGAL::parameters::no_lloyd(), CGAL::parameters::no_odt(),
                      CGAL::parameters::perturb(CGAL::parameters::time_limit = 0, CGAL::parameters::sliver_bound = 8),
                      CGAL::parameters::exude(CGAL::parameters::time_limit = 0, CGAL::parameters::sliver_bound = 15));
  mesh::TetMesh result = extract_mesh(complex, parts);

  TetrahedralizeReport made;
  made.tets_per_region.assign(parts.size(), 0);
  made.region_volumes.assign(parts.size(), 0.0);
  for (Index t = 0; t < result.num_tets(); ++t) {
    const auto r = static_cast<std::size_t>(result.region(t));
    ++made.tets_per_region[r];
    made.region_volumes[r] += mesh::signed_volume(result.rest, result.tets, t);
  }
  for (std::size_t r = 0; r < parts.size(); ++r) {
    if (made.tets_per_region[r] == 0) {
      throw InputError(what + ": part \"" + parts[r].region +
                       "\" got no elements: it is empty, hidden by earlier parts, or thinner than the elements "
                       "(lower element_size or add a size zone on it)");
    }
  }
  made.quality = mesh::mesh_quality(result.rest, result.tets);
  if (options.min_dihedral_deg > 0 && made.quality.min_dihedral_deg < options.min_dihedral_deg) {
    throw InputError(what + ": the smallest dihedral angle is " + std::to_string(made.quality.min_dihedral_deg) +
                     " degrees, below min_dihedral_deg = " + std::to_string(options.min_dihedral_deg) +
                     " after sliver removal (lower element_size near thin parts, or relax the bound)");
  }
  add_region_surfaces(result);
  made.seconds = seconds_since(start);
  if (report != nullptr) *report = made;
  return result;
}

}  // namespace sinew::surface
