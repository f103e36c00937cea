#include "Labeling/CellLabeling.h"

#include <algorithm>
#include <climits>
#include <tuple>

namespace boolsurf
{
namespace
{

// A crossing between two cells: the label change, per shape, when stepping from Cell0 to
// Cell1 (the opposite step subtracts it).
struct Crossing
{
  int Cell0, Cell1;
  long long Location;
  std::vector<std::pair<int, int>> Delta; // (shape, change), shapes sorted
};

std::vector<Crossing> GroupCrossings(const LabelingInput& input)
{
  const int nodes = input.GetNumberOfNodes();
  struct Key
  {
    int Cell0, Cell1;
    long long Location;
    int Shape, Change;
  };
  std::vector<Key> keys;
  keys.reserve(input.Arcs.size());
  for (const CellArc& a : input.Arcs)
  {
    if (a.RightCell < 0 || a.LeftCell < 0 || a.RightCell >= nodes || a.LeftCell >= nodes ||
      a.Shape < 0 || a.Shape >= input.NumberOfShapes)
    {
      continue;
    }
    // Stepping right -> left adds 1; store with the lower cell first. From a cell to itself,
    // only the direction along the place tells a curve from its reverse.
    if (a.RightCell == a.LeftCell)
    {
      keys.push_back({ a.RightCell, a.LeftCell, a.Location, a.Shape, a.Direction < 0 ? -1 : 1 });
    }
    else if (a.RightCell < a.LeftCell)
    {
      keys.push_back({ a.RightCell, a.LeftCell, a.Location, a.Shape, +1 });
    }
    else
    {
      keys.push_back({ a.LeftCell, a.RightCell, a.Location, a.Shape, -1 });
    }
  }
  std::sort(keys.begin(),
    keys.end(),
    [](const Key& a, const Key& b)
    {
      return std::tie(a.Cell0, a.Cell1, a.Location, a.Shape) <
        std::tie(b.Cell0, b.Cell1, b.Location, b.Shape);
    });
  std::vector<Crossing> crossings;
  for (size_t i = 0; i < keys.size();)
  {
    Crossing c{ keys[i].Cell0, keys[i].Cell1, keys[i].Location, {} };
    for (; i < keys.size() && keys[i].Cell0 == c.Cell0 && keys[i].Cell1 == c.Cell1 &&
         keys[i].Location == c.Location;
         ++i)
    {
      if (!c.Delta.empty() && c.Delta.back().first == keys[i].Shape)
      {
        c.Delta.back().second += keys[i].Change; // overlapping curves of one shape add up
      }
      else
      {
        c.Delta.emplace_back(keys[i].Shape, keys[i].Change);
      }
    }
    crossings.push_back(std::move(c));
  }
  // Links change no label: crossings without a delta, at a place of their own.
  for (const auto& link : input.Links)
  {
    if (link.first >= 0 && link.second >= 0 && link.first < nodes && link.second < nodes &&
      link.first != link.second)
    {
      crossings.push_back({ std::min(link.first, link.second),
        std::max(link.first, link.second),
        -1 - static_cast<long long>(crossings.size()),
        {} });
    }
  }
  return crossings;
}

} // namespace

//------------------------------------------------------------------------------
void LabelingInput::SetZeroCell(int cell)
{
  const int component = this->CellComponent.empty() ? 0 : this->CellComponent[cell];
  if (static_cast<int>(this->ZeroCells.size()) <= component)
  {
    this->ZeroCells.resize(component + 1, -1);
  }
  this->ZeroCells[component] = cell;
}

//------------------------------------------------------------------------------
LabelingResult LabelCells(const LabelingInput& input)
{
  // Cells and plugs are labeled alike (nodes); the plugs are dropped at the end.
  const int nc = input.GetNumberOfNodes();
  const int ns = input.NumberOfShapes;
  LabelingResult result;
  result.NumberOfShapes = ns;
  result.ShapeIds = input.ShapeIds;
  result.Labels.assign(static_cast<size_t>(nc) * ns, 0);
  result.ShapeConsistent.assign(ns, 1);

  const std::vector<Crossing> crossings = GroupCrossings(input);
  // Cell -> incident crossings (CSR).
  std::vector<int> offset(nc + 1, 0);
  for (const Crossing& c : crossings)
  {
    ++offset[c.Cell0 + 1];
    if (c.Cell1 != c.Cell0)
    {
      ++offset[c.Cell1 + 1];
    }
  }
  for (int i = 0; i < nc; ++i)
  {
    offset[i + 1] += offset[i];
  }
  std::vector<int> incident(offset[nc]);
  std::vector<int> fill(offset.begin(), offset.end() - 1);
  for (int i = 0; i < static_cast<int>(crossings.size()); ++i)
  {
    incident[fill[crossings[i].Cell0]++] = i;
    if (crossings[i].Cell1 != crossings[i].Cell0)
    {
      incident[fill[crossings[i].Cell1]++] = i;
    }
  }

  auto componentOf = [&](int cell)
  { return input.CellComponent.empty() ? 0 : input.CellComponent[cell]; };
  auto conflict = [&](int shape, int cell, int had, int other)
  {
    if (result.ShapeConsistent[shape])
    {
      result.ShapeConsistent[shape] = 0;
      result.Conflicts.push_back({ shape, cell, had, other });
    }
  };

  std::vector<char> visited(nc, 0);
  std::vector<int> queue;
  queue.reserve(nc);
  std::vector<int> label(ns);
  for (int seedCell = 0; seedCell < nc; ++seedCell)
  {
    if (visited[seedCell])
    {
      continue;
    }
    // Start each component at its zero cell when it has one.
    const int comp = componentOf(seedCell);
    int seed = seedCell;
    const bool hasZero = comp >= 0 && comp < static_cast<int>(input.ZeroCells.size()) &&
      input.ZeroCells[comp] >= 0 && input.ZeroCells[comp] < nc && !visited[input.ZeroCells[comp]];
    if (hasZero)
    {
      seed = input.ZeroCells[comp];
    }
    queue.clear();
    queue.push_back(seed);
    visited[seed] = 1;
    for (size_t head = 0; head < queue.size(); ++head)
    {
      const int cell = queue[head];
      const int* here = &result.Labels[static_cast<size_t>(cell) * ns];
      for (int k = offset[cell]; k < offset[cell + 1]; ++k)
      {
        const Crossing& c = crossings[incident[k]];
        // A crossing from a cell to itself (a curve inside one cell, e.g. a single loop on a
        // torus): any nonzero change is a conflict right away.
        if (c.Cell0 == c.Cell1)
        {
          for (const auto& d : c.Delta)
          {
            if (d.second != 0)
            {
              conflict(d.first, cell, here[d.first], here[d.first] + d.second);
            }
          }
          continue;
        }
        const int other = c.Cell0 == cell ? c.Cell1 : c.Cell0;
        const int sign = c.Cell0 == cell ? +1 : -1;
        std::copy(here, here + ns, label.begin());
        for (const auto& d : c.Delta)
        {
          label[d.first] += sign * d.second;
        }
        int* there = &result.Labels[static_cast<size_t>(other) * ns];
        if (!visited[other])
        {
          visited[other] = 1;
          std::copy(label.begin(), label.end(), there);
          queue.push_back(other);
          continue;
        }
        for (int s = 0; s < ns; ++s)
        {
          if (there[s] != label[s])
          {
            // Reported at a cell: a plug is no cell of the user's; from `cell`'s side, the
            // plug's label gives `cell` another one.
            if (other >= input.NumberOfCells)
            {
              conflict(s, cell, here[s], there[s] - (label[s] - here[s]));
            }
            else
            {
              conflict(s, other, there[s], label[s]);
            }
          }
        }
      }
    }
    if (!hasZero)
    {
      // Closed component without a chosen zero cell: shift each shape so its minimum is 0.
      for (int s = 0; s < ns; ++s)
      {
        int lowest = INT_MAX;
        for (int cell : queue)
        {
          lowest = std::min(lowest, result.Labels[static_cast<size_t>(cell) * ns + s]);
        }
        for (int cell : queue)
        {
          result.Labels[static_cast<size_t>(cell) * ns + s] -= lowest;
        }
      }
    }
  }
  result.Labels.resize(static_cast<size_t>(input.NumberOfCells) * ns);
  return result;
}

} // namespace boolsurf
