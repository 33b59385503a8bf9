/*
 * pcl_flowseg - the earth mover's distance between two small weighted sets, exactly.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "transport_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl_flowseg {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity ();

/** The residual network of a transportation problem: sources 0..n-1, sinks n..n+m-1. */
struct Transport
{
  const Eigen::MatrixXd& cost;
  std::vector<double> supply, demand;
  Eigen::MatrixXd flow;
  std::vector<double> potential; ///< keeps reduced costs >= 0 (Johnson)
  double tolerance = 0.0;

  std::size_t n () const { return supply.size (); }
  std::size_t m () const { return demand.size (); }

  /** Dijkstra from every source with supply left (dense: the network is complete bipartite).
    * Returns the nearest sink with demand left, or -1; \a previous holds the path. */
  int shortestPaths (std::vector<double>& distance, std::vector<int>& previous) const;
  /** Sends as much as the path to \a sink allows and updates the potentials. */
  void augment (int sink, const std::vector<double>& distance, const std::vector<int>& previous);
};

int
Transport::shortestPaths (std::vector<double>& distance, std::vector<int>& previous) const
{
  const std::size_t nodes = n () + m ();
  distance.assign (nodes, kInfinity);
  previous.assign (nodes, -1);
  std::vector<bool> done (nodes, false);
  for (std::size_t i = 0; i < n (); ++i)
    if (supply[i] > tolerance)
      distance[i] = 0.0;
  for (std::size_t step = 0; step < nodes; ++step)
  {
    std::size_t u = nodes;
    for (std::size_t v = 0; v < nodes; ++v)
      if (!done[v] && distance[v] < kInfinity && (u == nodes || distance[v] < distance[u]))
        u = v;
    if (u == nodes)
      break;
    done[u] = true;
    if (u >= n () && demand[u - n ()] > tolerance)
      return static_cast<int> (u);
    const auto relax = [&] (std::size_t v, double reduced) {
      if (!done[v] && distance[u] + reduced < distance[v])
      {
        distance[v] = distance[u] + std::max (0.0, reduced);
        previous[v] = static_cast<int> (u);
      }
    };
    if (u < n ()) // forward arcs to every sink
      for (std::size_t j = 0; j < m (); ++j)
        relax (n () + j, cost (static_cast<Eigen::Index> (u), static_cast<Eigen::Index> (j)) + potential[u] - potential[n () + j]);
    else // backward arcs along flow already sent
      for (std::size_t i = 0; i < n (); ++i)
        if (flow (static_cast<Eigen::Index> (i), static_cast<Eigen::Index> (u - n ())) > tolerance)
          relax (i, -cost (static_cast<Eigen::Index> (i), static_cast<Eigen::Index> (u - n ())) + potential[u] - potential[i]);
  }
  return -1;
}

void
Transport::augment (int sink, const std::vector<double>& distance, const std::vector<int>& previous)
{
  double amount = demand[static_cast<std::size_t> (sink) - n ()];
  int v = sink;
  for (; previous[static_cast<std::size_t> (v)] >= 0; v = previous[static_cast<std::size_t> (v)])
    if (static_cast<std::size_t> (v) < n ()) // v is a source reached backwards from sink p
      amount = std::min (amount, flow (v, previous[static_cast<std::size_t> (v)] - static_cast<int> (n ())));
  amount = std::min (amount, supply[static_cast<std::size_t> (v)]);
  supply[static_cast<std::size_t> (v)] -= amount;
  demand[static_cast<std::size_t> (sink) - n ()] -= amount;
  for (int w = sink; previous[static_cast<std::size_t> (w)] >= 0; w = previous[static_cast<std::size_t> (w)])
  {
    const int p = previous[static_cast<std::size_t> (w)];
    if (static_cast<std::size_t> (w) >= n ())
      flow (p, w - static_cast<int> (n ())) += amount;
    else
      flow (w, p - static_cast<int> (n ())) -= amount;
  }
  const double reach = distance[static_cast<std::size_t> (sink)];
  for (std::size_t u = 0; u < potential.size (); ++u)
    potential[u] += std::min (distance[u], reach);
}

} // namespace

double
transportDistance (const std::vector<double>& from, const std::vector<double>& to, const Eigen::MatrixXd& cost)
{
  double from_total = 0.0, to_total = 0.0;
  for (double w : from)
    from_total += w;
  for (double w : to)
    to_total += w;
  if (from.empty () || to.empty () || !(from_total > 0.0) || !(to_total > 0.0))
    return 0.0;
  Transport t{cost, from, to, Eigen::MatrixXd::Zero (static_cast<Eigen::Index> (from.size ()), static_cast<Eigen::Index> (to.size ())),
              std::vector<double> (from.size () + to.size (), 0.0), 1e-12 * from_total};
  for (double& w : t.demand)
    w *= from_total / to_total;
  std::vector<double> distance;
  std::vector<int> previous;
  const std::size_t most_steps = 4 * (from.size () + to.size ()) * (from.size () + to.size ()) + 16;
  for (std::size_t step = 0; step < most_steps; ++step)
  {
    const int sink = t.shortestPaths (distance, previous);
    if (sink < 0)
      break;
    t.augment (sink, distance, previous);
  }
  return (t.flow.array () * cost.array ()).sum ();
}

} // namespace pcl_flowseg
