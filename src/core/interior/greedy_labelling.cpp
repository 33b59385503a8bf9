/*
 * pcl_flowseg - internal: cells labelled inside or outside by evidence on their facets, most certain first.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "core/interior/greedy_labelling.h"

#include "core/geometry/cell_geometry.h"
#include "core/interior/open_exterior.h"
#include "core/interior/sensor_rays.h"
#include "core/support/cell_heap.h"
#include "core/support/parallel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>

namespace pcl_flowseg {
namespace core {

namespace {

class GreedyLabelling
{
public:
  GreedyLabelling (const std::vector<Eigen::Vector3d>& vertices, std::vector<FlowCell>& cells, int dimension,
                   std::vector<GreedyCell>&& measured)
    : vertices_ (vertices), cells_ (cells), d_ (dimension), f_ (dimension + 1), state_ (std::move (measured)),
      queue_ (cells.size ())
  {
  }

  /** The outside beyond the convex hull. The hull cells are found on all workers; their evidence
    * is then given in cell order, as one loop would. */
  void
  hullEvidence ()
  {
    const std::vector<int> hull = gatherListInOrder<int> (state_.size (), [&] (std::size_t begin, std::size_t end, std::vector<int>& found) {
      for (std::size_t c = begin; c < end; ++c)
        for (int i = 0; i < f_; ++i)
          if (state_[c].neighbors[static_cast<std::size_t> (i)] < 0)
          {
            found.push_back (static_cast<int> (c));
            break;
          }
    });
    for (int h : hull)
    {
      const std::size_t c = static_cast<std::size_t> (h);
      for (int i = 0; i < f_; ++i)
        if (state_[c].neighbors[static_cast<std::size_t> (i)] < 0)
        {
          const double s = agreement (c, i);
          evidence (c, s >= 0, std::abs (s));
        }
    }
  }

  /** Oriented normals: a cell whose circumcentre lies along the normals of its vertices is outside.
    * Vertices with a zero (or non-finite) normal say nothing. */
  void
  normalEvidence (const std::vector<Eigen::Vector3d>& vertex_normals)
  {
    const auto usable = [&] (std::size_t v) { return vertex_normals[v].allFinite () && vertex_normals[v].squaredNorm () > 0; };
    // Mean cosine between each vertex's normal and the direction to the circumcentre, measured on
    // all workers (cells with no usable normal skip the circumcentre); evidence is given in cell order.
    std::vector<double> mean_cosine (cells_.size (), 0.0);
    parallelFor (cells_.size (), [&] (std::size_t c) {
      bool any = false;
      for (int i = 0; i < f_ && !any; ++i)
        any = usable (static_cast<std::size_t> (cells_[c].vertices[i]));
      if (!any)
        return;
      const Eigen::Vector3d centre = cellCircumcentre (vertices_, cells_[c], d_);
      double u = 0.0;
      int count = 0;
      for (int i = 0; i < f_; ++i)
      {
        const std::size_t v = static_cast<std::size_t> (cells_[c].vertices[i]);
        const Eigen::Vector3d to_centre = centre - vertices_[v];
        const double len = to_centre.norm ();
        if (len > 0 && usable (v))
        {
          u += to_centre.dot (vertex_normals[v].normalized ()) / len;
          ++count;
        }
      }
      mean_cosine[c] = count > 0 ? u / count : 0.0;
    });
    for (std::size_t c = 0; c < cells_.size (); ++c)
      if (mean_cosine[c] != 0.0)
        evidence (c, mean_cosine[c] > 0, std::abs (mean_cosine[c]));
  }

  /** Sensor rays: everything between the sensor and a sample (one of the first \a seen vertices) is
    * free space. Returns the cells marked. */
  std::size_t
  rayEvidence (const Eigen::Vector3d& viewpoint, std::size_t seen)
  {
    std::size_t marked = 0;
    const std::vector<std::uint8_t> free_space = freeSpaceCells (vertices_, seen, cells_, d_, viewpoint, marked);
    for (std::size_t c = 0; c < cells_.size (); ++c)
      if (free_space[c])
        evidence (c, true, 1.0); // as strong as the strongest geometric evidence
    return marked;
  }

  /** Wide openings: the cells a ball of \a opening_spacings sample spacings reaches from beyond
    * the hull are outside, as strongly as on a sensor ray; without \a given_normals, the
    * directions from the samples to those cells orient them (normalEvidence). Returns the cells
    * marked. */
  std::size_t
  openingEvidence (double opening_spacings, bool given_normals)
  {
    const double opening = opening_spacings * medianNearestDistance (vertices_, cells_);
    const std::vector<std::uint8_t> reached = openExteriorCells (vertices_, cells_, opening);
    if (!given_normals)
      normalEvidence (openingNormals (vertices_, cells_, reached));
    std::size_t marked = 0;
    for (std::size_t c = 0; c < cells_.size (); ++c)
      if (reached[c])
      {
        evidence (c, true, 1.0);
        ++marked;
      }
    return marked;
  }

  /** The greedy pass: the most certain undecided cell takes its label and tells its neighbours.
    * A cell's evidence no longer changes once it is labelled, so its label is the side its evidence
    * favours, read off at the end (a cell without any evidence is outside). */
  void
  propagate ()
  {
    while (!queue_.empty ())
    {
      const std::size_t c = static_cast<std::size_t> (queue_.pop ());
      const GreedyCell& state = state_[c];
      // The pass is bound by memory latency (cells are visited in margin order, all over memory):
      // start loading the likely next cell and the neighbours before they are needed.
      if (!queue_.empty ())
        __builtin_prefetch (&state_[static_cast<std::size_t> (queue_.top ())]);
      prefetchNeighbours (c);
      const bool outside = isOutside (state);
      for (int i = 0; i < f_; ++i)
      {
        const int nb = state.neighbors[static_cast<std::size_t> (i)];
        if (nb < 0 || queue_.retired (nb))
          continue;
        const double s = state.agreement[static_cast<std::size_t> (i)];
        evidence (static_cast<std::size_t> (nb), outside == (s >= 0), std::abs (s));
        prefetchNeighbours (static_cast<std::size_t> (nb));
      }
    }
    parallelFor (cells_.size (), [&] (std::size_t c) { cells_[c].inside = isOutside (state_[c]) ? 0 : 1; });
  }

private:
  static bool isOutside (const GreedyCell& state) { return state.out_score >= state.in_score; }

  /** A cell that just heard evidence is likely among the next popped (the front moves through
    * its neighbours): its neighbours start loading now, a whole pop ahead of their use. */
  void
  prefetchNeighbours (std::size_t c) const
  {
    const GreedyCell& state = state_[c];
    for (int i = 0; i < f_; ++i)
      if (state.neighbors[static_cast<std::size_t> (i)] >= 0)
        __builtin_prefetch (&state_[static_cast<std::size_t> (state.neighbors[static_cast<std::size_t> (i)])]);
  }

  double agreement (std::size_t c, int i) const { return state_[c].agreement[static_cast<std::size_t> (i)]; }

  /** Evidence adds up: a cell hears every labelled neighbour, so one confident but wrong facet (a
    * flat cell's sphere) is outvoted. */
  void
  evidence (std::size_t c, bool outside, double weight)
  {
    GreedyCell& state = state_[c];
    (outside ? state.out_score : state.in_score) += weight;
    queue_.update (static_cast<int> (c), std::abs (state.in_score - state.out_score));
  }

  const std::vector<Eigen::Vector3d>& vertices_;
  std::vector<FlowCell>& cells_;
  const int d_, f_;
  std::vector<GreedyCell> state_;
  CellHeap queue_; ///< undecided cells that have heard evidence, largest margin first
};

} // namespace

ExtraEvidence
labelCellsGreedily (const std::vector<Eigen::Vector3d>& vertices, std::vector<FlowCell>& cells, int dimension,
                    const InteriorParameters& params, const std::vector<Eigen::Vector3d>& vertex_normals,
                    std::size_t seen_vertices)
{
  return labelCellsGreedily (vertices, cells, dimension, params, vertex_normals,
                             seen_vertices, measureFacetAgreements (vertices, cells, dimension));
}

ExtraEvidence
labelCellsGreedily (const std::vector<Eigen::Vector3d>& vertices, std::vector<FlowCell>& cells, int dimension,
                    const InteriorParameters& params, const std::vector<Eigen::Vector3d>& vertex_normals,
                    std::size_t seen_vertices, std::vector<GreedyCell>&& measured)
{
  GreedyLabelling labelling (vertices, cells, dimension, std::move (measured));
  labelling.hullEvidence ();
  if (!vertex_normals.empty ())
    labelling.normalEvidence (vertex_normals);
  ExtraEvidence extra;
  if (params.viewpoint)
    extra.ray_cells = labelling.rayEvidence (*params.viewpoint, seen_vertices);
  else if (dimension == 3 && params.exterior_opening > 0.0)
    extra.opening_cells = labelling.openingEvidence (params.exterior_opening, !vertex_normals.empty ());
  labelling.propagate ();
  return extra;
}

} // namespace core
} // namespace pcl_flowseg
