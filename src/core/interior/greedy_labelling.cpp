/*
 * pcl_flowseg - internal: cells labelled inside or outside by evidence on their facets, most certain first.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/interior/greedy_labelling.h"

#include "core/geometry/cell_geometry.h"
#include "core/interior/nn_crust.h"
#include "core/interior/sensor_rays.h"
#include "core/support/cell_heap.h"
#include "core/support/huge_pages.h"
#include "core/support/parallel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_set>

namespace pcl_flowseg {
namespace core {

namespace {

/** Least agreement of an edge with the NN-crust's verdict in 2D: crust edges separate the two
  * sides at least this strongly, the other edges join them at least this strongly. */
constexpr double kCrustWeight = 0.5;

class GreedyLabelling
{
public:
  GreedyLabelling (const std::vector<Eigen::Vector3d>& vertices, std::vector<FlowCell>& cells, int dimension)
    : vertices_ (vertices), cells_ (cells), d_ (dimension), f_ (dimension + 1), queue_ (cells.size ())
  {
    assignOnHugePages (centre_, cells.size (), Eigen::Vector3d (Eigen::Vector3d::Zero ()));
    parallelFor (cells.size (), [&] (std::size_t c) { centre_[c] = cellCircumcentre (vertices_, cells_[c], d_); });
    measureAgreements ();
  }

  /** The outside beyond the convex hull. */
  void
  hullEvidence ()
  {
    for (std::size_t c = 0; c < cells_.size (); ++c)
      for (int i = 0; i < f_; ++i)
        if (cells_[c].neighbors[i] < 0)
        {
          const double s = agreement (c, i);
          evidence (c, s >= 0, std::abs (s));
        }
  }

  /** Oriented normals: a cell whose circumcentre lies along the normals of its vertices is outside. */
  void
  normalEvidence (const std::vector<Eigen::Vector3d>& vertex_normals)
  {
    for (std::size_t c = 0; c < cells_.size (); ++c)
    {
      double u = 0.0;
      int count = 0;
      for (int i = 0; i < f_; ++i)
      {
        const std::size_t v = static_cast<std::size_t> (cells_[c].vertices[i]);
        const Eigen::Vector3d to_centre = centre_[c] - vertices_[v];
        const double len = to_centre.norm ();
        if (len > 0 && vertex_normals[v].allFinite () && vertex_normals[v].squaredNorm () > 0)
        {
          u += to_centre.dot (vertex_normals[v].normalized ()) / len;
          ++count;
        }
      }
      if (count > 0)
        evidence (c, u > 0, std::abs (u) / count);
    }
  }

  /** Sensor rays: everything between the sensor and a sample is free space. Returns the cells marked. */
  std::size_t
  rayEvidence (const Eigen::Vector3d& viewpoint)
  {
    std::size_t marked = 0;
    const std::vector<std::uint8_t> free_space = freeSpaceCells (vertices_, cells_, d_, viewpoint, marked);
    for (std::size_t c = 0; c < cells_.size (); ++c)
      if (free_space[c])
        evidence (c, true, 1.0); // as strong as the strongest geometric evidence
    return marked;
  }

  /** The greedy pass: the most certain undecided cell takes its label and tells its neighbours.
    * A cell's evidence no longer changes once it is labelled, so its label is the side its evidence
    * favours, read off at the end (a cell without any evidence is outside). */
  void
  propagate ()
  {
    std::vector<Eigen::Vector3d> ().swap (centre_); // every use is behind: the memory is better free
    while (!queue_.empty ())
    {
      const std::size_t c = static_cast<std::size_t> (queue_.pop ());
      const CellState& state = state_[c];
      // The pass is bound by memory latency (cells are visited in margin order, all over memory):
      // start loading the likely next cell and the neighbours before they are needed.
      if (!queue_.empty ())
        __builtin_prefetch (&state_[static_cast<std::size_t> (queue_.top ())]);
      for (int i = 0; i < f_; ++i)
        if (state.neighbors[static_cast<std::size_t> (i)] >= 0)
          __builtin_prefetch (&state_[static_cast<std::size_t> (state.neighbors[static_cast<std::size_t> (i)])]);
      const bool outside = isOutside (state);
      for (int i = 0; i < f_; ++i)
      {
        const int nb = state.neighbors[static_cast<std::size_t> (i)];
        if (nb < 0 || queue_.retired (nb))
          continue;
        const double s = state.agreement[static_cast<std::size_t> (i)];
        evidence (static_cast<std::size_t> (nb), outside == (s >= 0), std::abs (s));
      }
    }
    for (std::size_t c = 0; c < cells_.size (); ++c)
      cells_[c].inside = isOutside (state_[c]) ? 0 : 1;
  }

private:
  /** What the greedy pass reads and writes for one cell, in one cache line: the pass visits cells
    * in the order of their margins, all over memory, so each cell should cost one miss, not one
    * per array. */
  struct alignas (64) CellState
  {
    std::array<int, 4> neighbors;
    std::array<double, 4> agreement; ///< see measureAgreement
    double in_score, out_score;      ///< summed evidence for inside and outside
  };

  /** Agreement across facet i of cell c: > 0 same side, < 0 opposite sides, |value| = confidence.
    * The cosine of the angle between the two spheres, measured at a facet vertex (on both) as the
    * angle between the directions to the two centres: unlike the law of cosines this stays
    * accurate for the huge spheres of flat cells, whose centres are far away but in a
    * well-defined direction. */
  double
  measureAgreement (std::size_t c, int i, const std::unordered_set<std::uint64_t>& crust) const
  {
    const FlowCell& cell = cells_[c];
    const int nb = cell.neighbors[i];
    const Eigen::Vector3d& on = vertices_[static_cast<std::size_t> (cell.vertices[(i + 1) % f_])];
    const Eigen::Vector3d to_a = (centre_[c] - on).normalized ();
    double s = nb < 0 ? to_a.dot (outwardFacetNormal (vertices_, cell, i, d_))
                      : to_a.dot ((centre_[static_cast<std::size_t> (nb)] - on).normalized ());
    if (!std::isfinite (s))
      s = 0.0;
    s = std::max (-1.0, std::min (1.0, s));
    if (d_ == 2)
    {
      const bool on_crust = crust.count (edgeKey (cell.vertices[(i + 1) % 3], cell.vertices[(i + 2) % 3])) > 0;
      s = on_crust ? std::min (s, -kCrustWeight) : std::max (s, kCrustWeight);
    }
    return s;
  }

  /** Every value the greedy pass may ask for, computed up front in parallel (the pass itself is
    * sequential). */
  void
  measureAgreements ()
  {
    const std::unordered_set<std::uint64_t> crust = d_ == 2 ? nnCrust (vertices_, cells_) : std::unordered_set<std::uint64_t> ();
    assignOnHugePages (state_, cells_.size ());
    parallelFor (cells_.size (), [&] (std::size_t c) {
      CellState& state = state_[c];
      state.neighbors = cells_[c].neighbors;
      state.agreement = {{0.0, 0.0, 0.0, 0.0}};
      for (int i = 0; i < f_; ++i)
        state.agreement[static_cast<std::size_t> (i)] = measureAgreement (c, i, crust);
      state.in_score = state.out_score = 0.0;
    });
  }

  static bool isOutside (const CellState& state) { return state.out_score >= state.in_score; }

  double agreement (std::size_t c, int i) const { return state_[c].agreement[static_cast<std::size_t> (i)]; }

  /** Evidence adds up: a cell hears every labelled neighbour, so one confident but wrong facet (a
    * flat cell's sphere) is outvoted. */
  void
  evidence (std::size_t c, bool outside, double weight)
  {
    CellState& state = state_[c];
    (outside ? state.out_score : state.in_score) += weight;
    queue_.update (static_cast<int> (c), std::abs (state.in_score - state.out_score));
  }

  const std::vector<Eigen::Vector3d>& vertices_;
  std::vector<FlowCell>& cells_;
  const int d_, f_;
  std::vector<Eigen::Vector3d> centre_;
  std::vector<CellState> state_;
  CellHeap queue_; ///< undecided cells that have heard evidence, largest margin first
};

} // namespace

std::size_t
labelCellsGreedily (const std::vector<Eigen::Vector3d>& vertices, std::vector<FlowCell>& cells, int dimension,
                    const InteriorParameters& params, const std::vector<Eigen::Vector3d>& vertex_normals)
{
  GreedyLabelling labelling (vertices, cells, dimension);
  labelling.hullEvidence ();
  if (!vertex_normals.empty ())
    labelling.normalEvidence (vertex_normals);
  const std::size_t ray_cells = params.viewpoint ? labelling.rayEvidence (*params.viewpoint) : 0;
  labelling.propagate ();
  return ray_cells;
}

} // namespace core
} // namespace pcl_flowseg
