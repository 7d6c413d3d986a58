#include "support/triangulation_checks.h"

#include <algorithm>

#include <delpsc/kernel/predicates.h>

namespace delpsc::test {

using delaunay::PointStatus;
using delaunay::RegularTriangulation;

std::vector<Quad> finite_cell_quads(const RegularTriangulation& t,
                                    const std::vector<std::uint32_t>& names) {
  std::vector<Quad> quads;
  t.for_each_finite_cell([&](delaunay::CellId c) {
    Quad q;
    for (int i = 0; i < 4; ++i) q[i] = names.empty() ? t.vertex(c, i) : names[t.vertex(c, i)];
    std::sort(q.begin(), q.end());
    quads.push_back(q);
  });
  std::sort(quads.begin(), quads.end());
  return quads;
}

std::vector<std::uint32_t> points_with_status(const RegularTriangulation& t, PointStatus status,
                                              const std::vector<std::uint32_t>& names) {
  std::vector<std::uint32_t> ids;
  for (std::uint32_t p = 0; p < t.number_of_points(); ++p)
    if (t.status(p) == status) ids.push_back(names.empty() ? p : names[p]);
  std::sort(ids.begin(), ids.end());
  return ids;
}

std::vector<Quad> brute_force_regular_cells(const std::vector<WeightedPoint>& points) {
  const auto n = static_cast<std::uint32_t>(points.size());
  std::vector<Quad> quads;
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = a + 1; b < n; ++b)
      for (std::uint32_t c = b + 1; c < n; ++c)
        for (std::uint32_t d = c + 1; d < n; ++d) {
          const double* q[4] = {points[a].data(), points[b].data(), points[c].data(), points[d].data()};
          const int o = kernel::orient3d(q[0], q[1], q[2], q[3]);
          if (o == 0) continue;
          if (o < 0) std::swap(q[2], q[3]);
          bool empty = true;
          for (std::uint32_t e = 0; e < n && empty; ++e) {
            if (e == a || e == b || e == c || e == d) continue;
            empty = kernel::power_test_perturbed(q[0], q[1], q[2], q[3], points[e].data()) < 0;
          }
          if (empty) quads.push_back({a, b, c, d});
        }
  std::sort(quads.begin(), quads.end());
  return quads;
}

std::string check_regular_against_all_points(const RegularTriangulation& t) {
  std::vector<std::uint32_t> live;
  for (std::uint32_t p = 0; p < t.number_of_points(); ++p)
    if (t.status(p) == PointStatus::vertex || t.status(p) == PointStatus::hidden) live.push_back(p);
  std::string problem;
  t.for_each_finite_cell([&](delaunay::CellId c) {
    if (!problem.empty()) return;
    const double* q[4];
    for (int i = 0; i < 4; ++i) q[i] = t.point(t.vertex(c, i)).data();
    for (const std::uint32_t p : live) {
      if (t.index_of(c, p) >= 0) continue;
      const double* x = t.point(p).data();
      int at = -1;
      for (int i = 0; i < 4; ++i)
        if (q[i][0] == x[0] && q[i][1] == x[1] && q[i][2] == x[2]) at = i;
      const bool conflict = at >= 0 ? kernel::power_test(q[at], x) > 0
                                    : kernel::power_test_perturbed(q[0], q[1], q[2], q[3], x) > 0;
      if (conflict) {
        problem = "point " + std::to_string(p) + " is in conflict with cell " + std::to_string(c);
        return;
      }
    }
  });
  return problem;
}

std::string check_change_set(const RegularTriangulation& t, std::size_t cells_before,
                             const delaunay::ChangeSet& changes) {
  for (const auto c : changes.created)
    if (c >= t.cell_capacity() || !t.is_cell_alive(c)) return "a created cell is not alive";
  auto repeats = [](std::vector<delaunay::CellId> v) {
    std::sort(v.begin(), v.end());
    return std::adjacent_find(v.begin(), v.end()) != v.end();
  };
  if (repeats(changes.created)) return "a cell is reported created twice";
  if (repeats(changes.destroyed)) return "a cell is reported destroyed twice";
  for (const auto c : changes.destroyed)
    if (t.is_cell_alive(c) && std::find(changes.created.begin(), changes.created.end(), c) == changes.created.end())
      return "a destroyed cell is still alive and not reported re-created";
  if (cells_before - changes.destroyed.size() + changes.created.size() != t.number_of_cells())
    return "cells before - destroyed + created != cells after";
  return {};
}

}  // namespace delpsc::test
