/*
 * pcl_flowseg - the least total cost of a one-to-one assignment: the Hungarian method with
 * potentials, one row added at a time along a shortest augmenting path.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "assignment_cost.h"

#include <algorithm>
#include <limits>

namespace pcl_flowseg {

double
leastAssignmentCost (const std::vector<double>& cost, std::size_t rows, std::size_t columns)
{
  constexpr double kInfinity = std::numeric_limits<double>::infinity ();
  // Index 0 of the columns is a virtual column holding the row being added; rows and columns
  // count from 1 and row_of[j] == 0 marks a free column.
  std::vector<double> row_potential (rows + 1, 0.0), column_potential (columns + 1, 0.0), slack (columns + 1);
  std::vector<std::size_t> row_of (columns + 1, 0), came_from (columns + 1, 0);
  std::vector<char> visited (columns + 1), assigned (rows + 1, 0);
  // Start from each row's cheapest column (its potential), taken where that column is still free:
  // the paths below then only have to place the rows that collided.
  for (std::size_t row = 1; row <= rows; ++row)
  {
    const double* costs = &cost[(row - 1) * columns];
    const std::size_t cheapest = static_cast<std::size_t> (std::min_element (costs, costs + columns) - costs) + 1;
    row_potential[row] = costs[cheapest - 1];
    if (row_of[cheapest] == 0)
    {
      row_of[cheapest] = row;
      assigned[row] = 1;
    }
  }
  for (std::size_t added = 1; added <= rows; ++added)
  {
    if (assigned[added])
      continue;
    row_of[0] = added;
    std::size_t column = 0;
    std::fill (slack.begin (), slack.end (), kInfinity);
    std::fill (visited.begin (), visited.end (), 0);
    do // grow a shortest-path tree from the new row until it reaches a free column
    {
      visited[column] = 1;
      const std::size_t row = row_of[column];
      double delta = kInfinity;
      std::size_t next = 0;
      for (std::size_t j = 1; j <= columns; ++j)
      {
        if (visited[j])
          continue;
        const double reduced = cost[(row - 1) * columns + (j - 1)] - row_potential[row] - column_potential[j];
        if (reduced < slack[j])
        {
          slack[j] = reduced;
          came_from[j] = column;
        }
        if (slack[j] < delta)
        {
          delta = slack[j];
          next = j;
        }
      }
      for (std::size_t j = 0; j <= columns; ++j)
        if (visited[j])
        {
          row_potential[row_of[j]] += delta;
          column_potential[j] -= delta;
        }
        else
          slack[j] -= delta;
      column = next;
    } while (row_of[column] != 0);
    do // flip the assignment along the path back to the virtual column
    {
      const std::size_t previous = came_from[column];
      row_of[column] = row_of[previous];
      column = previous;
    } while (column != 0);
  }
  double total = 0.0;
  for (std::size_t j = 1; j <= columns; ++j)
    if (row_of[j] != 0)
      total += cost[(row_of[j] - 1) * columns + (j - 1)];
  return total;
}

} // namespace pcl_flowseg
