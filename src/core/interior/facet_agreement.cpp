/*
 * pcl_flowseg - internal: how strongly the two cells across each facet lie on the same side of the
 * sampled surface, measured for the greedy labelling.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/interior/facet_agreement.h"

#include "core/geometry/cell_geometry.h"
#include "core/interior/nn_crust.h"
#include "core/support/huge_pages.h"
#include "core/support/parallel.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_set>

namespace pcl_flowseg {
namespace core {

namespace {
/** Least agreement of an edge with the NN-crust's verdict in 2D: crust edges separate the two
  * sides at least this strongly, the other edges join them at least this strongly. */
constexpr double kCrustWeight = 0.5;

/** The agreement across facet \a i of cell \a c (see measureFacetAgreements). */
double
facetAgreement (const std::vector<Eigen::Vector3d>& vertices, const std::vector<FlowCell>& cells, int d,
                const std::vector<Eigen::Vector3d>& centre, std::size_t c, int i, const std::unordered_set<std::uint64_t>& crust)
{
  const FlowCell& cell = cells[c];
  const int f = d + 1;
  const int nb = cell.neighbors[i];
  const Eigen::Vector3d& on = vertices[static_cast<std::size_t> (cell.vertices[(i + 1) % f])];
  const Eigen::Vector3d to_a = (centre[c] - on).normalized ();
  double s = nb < 0 ? to_a.dot (outwardFacetNormal (vertices, cell, i, d))
                    : to_a.dot ((centre[static_cast<std::size_t> (nb)] - on).normalized ());
  if (!std::isfinite (s))
    s = 0.0;
  s = std::max (-1.0, std::min (1.0, s));
  if (d == 2)
  {
    const bool on_crust = crust.count (edgeKey (cell.vertices[(i + 1) % 3], cell.vertices[(i + 2) % 3])) > 0;
    s = on_crust ? std::min (s, -kCrustWeight) : std::max (s, kCrustWeight);
  }
  return s;
}
} // namespace

std::vector<GreedyCell>
measureFacetAgreements (const std::vector<Eigen::Vector3d>& vertices, const std::vector<FlowCell>& cells, int dimension)
{
  std::vector<Eigen::Vector3d> centre;
  assignOnHugePages (centre, cells.size (), Eigen::Vector3d (Eigen::Vector3d::Zero ()));
  parallelFor (cells.size (), [&] (std::size_t c) { centre[c] = cellCircumcentre (vertices, cells[c], dimension); });
  const std::unordered_set<std::uint64_t> crust = dimension == 2 ? nnCrust (vertices, cells) : std::unordered_set<std::uint64_t> ();
  std::vector<GreedyCell> measured;
  assignOnHugePages (measured, cells.size ());
  parallelFor (cells.size (), [&] (std::size_t c) {
    // The neighbours' centres lie all over memory: those of the cell 8 ahead start loading now.
    if (c + 8 < cells.size ())
      for (int i = 0; i <= dimension; ++i)
        if (cells[c + 8].neighbors[i] >= 0)
          __builtin_prefetch (&centre[static_cast<std::size_t> (cells[c + 8].neighbors[i])]);
    GreedyCell& cell = measured[c];
    cell.neighbors = cells[c].neighbors;
    cell.agreement = {{0.0, 0.0, 0.0, 0.0}};
    for (int i = 0; i <= dimension; ++i)
      cell.agreement[static_cast<std::size_t> (i)] = facetAgreement (vertices, cells, dimension, centre, c, i, crust);
    cell.in_score = cell.out_score = 0.0;
  });
  return measured;
}

} // namespace core
} // namespace pcl_flowseg
