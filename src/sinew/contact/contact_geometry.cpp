#include "sinew/contact/contact_geometry.hpp"

#include <cmath>

#include <fmt/format.h>

#include "sinew/core/error.hpp"

namespace sinew::contact {

void validate_contact_geometry(const ContactGeometry& g) {
  const Index bodies = static_cast<Index>(g.penalty.rows());
  if (g.penalty.cols() != bodies) throw InputError("contact: the penalty matrix must be square (bodies x bodies)");
  if (g.surface_body.size() != g.surface.rows())
    throw InputError("contact: surface_body must have one entry per surface triangle");
  if (g.tet_body.size() != g.tets.rows()) throw InputError("contact: tet_body must have one entry per tet");
  for (Index i = 0; i < bodies; ++i)
    for (Index j = 0; j < bodies; ++j) {
      const double e = g.penalty(i, j);
      if (!std::isfinite(e) || e < 0)
        throw InputError(fmt::format("contact: the penalty between bodies {} and {} is {} (must be finite and >= 0)",
                                     i, j, e));
      if (e != g.penalty(j, i)) throw InputError("contact: the penalty matrix must be symmetric");
    }
  auto check_scale = [](const VectorX& scale, Index expected, const char* what) {
    if (scale.size() == 0) return;
    if (scale.size() != expected)
      throw InputError(fmt::format("contact: {} penalty scale has {} entries for {} {}s", what, scale.size(),
                                   expected, what));
    for (Index k = 0; k < scale.size(); ++k)
      if (!std::isfinite(scale[k]) || scale[k] <= 0)
        throw InputError(fmt::format("contact: the penalty scale of {} {} is {} (must be finite and > 0)", what, k,
                                     scale[k]));
  };
  check_scale(g.surface_penalty_scale, g.surface.rows(), "triangle");
  check_scale(g.tet_penalty_scale, g.tets.rows(), "tet");
  for (Index k = 0; k < g.surface_body.size(); ++k)
    if (g.surface_body[k] < 0 || g.surface_body[k] >= bodies)
      throw InputError(fmt::format("contact: surface triangle {} has body {} (there are {} bodies)", k,
                                   g.surface_body[k], bodies));
  for (Index k = 0; k < g.tet_body.size(); ++k)
    if (g.tet_body[k] < 0 || g.tet_body[k] >= bodies)
      throw InputError(fmt::format("contact: tet {} has body {} (there are {} bodies)", k, g.tet_body[k], bodies));
  const Index nodes = static_cast<Index>(g.depth.size());
  if (!g.node_immovable.empty() && static_cast<Index>(g.node_immovable.size()) != nodes)
    throw InputError(fmt::format("contact: node_immovable has {} entries for {} nodes", g.node_immovable.size(), nodes));
  for (Index a = 0; a < nodes; ++a)
    if (!std::isfinite(g.depth[a]) || g.depth[a] < 0)
      throw InputError(fmt::format("contact: the material depth of node {} is {} (must be finite and >= 0)", a,
                                   g.depth[a]));
  if ((g.surface.size() > 0 && (g.surface.minCoeff() < 0 || g.surface.maxCoeff() >= nodes)) ||
      (g.tets.size() > 0 && (g.tets.minCoeff() < 0 || g.tets.maxCoeff() >= nodes)))
    throw InputError("contact: a surface triangle or tet refers to a node without a material depth");
}

}  // namespace sinew::contact
