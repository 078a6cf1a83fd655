#pragma once
// The span-list merging rules of CSG (thesis 3.1, [Requicha 1980]) on sorted,
// disjoint span lists. Shared by the CSG nodes and their tests.
//  - union: overlapping or touching spans coalesce (two solids that share a
//    face have no surface between them);
//  - intersection: the later enter and the earlier leave of overlapping spans;
//  - difference: where a subtracted span cuts a span, its ends become ends of
//    the result with normals flipped (they must point out of the result, i.e.
//    into the subtracted solid);
//  - spans of zero length enclose no volume and are dropped.
#include <algorithm>

#include "render/shapes/primitive.hpp"

namespace lattice {

// Sorts `list` by enter and coalesces overlapping/touching spans in place.
template <typename T>
void coalesceSpans(SpanList<T>& list) {
  if (list.empty()) return;
  std::sort(list.begin(), list.end(), [](const Span<T>& a, const Span<T>& b) { return a.enter.t < b.enter.t; });
  std::size_t kept = 0;
  for (std::size_t n = 1; n < list.size(); ++n) {
    Span<T>& cur = list[kept];
    const Span<T>& next = list[n];
    if (next.enter.t <= cur.leave.t) {
      if (next.leave.t > cur.leave.t) cur.leave = next.leave;
    } else {
      list[++kept] = next;
    }
  }
  while (list.size() > kept + 1) list.pop_back();
}

template <typename T>
void intersectSpans(const SpanList<T>& a, const SpanList<T>& b, SpanList<T>& out) {
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    const Hit<T>& enter = a[i].enter.t >= b[j].enter.t ? a[i].enter : b[j].enter;
    const Hit<T>& leave = a[i].leave.t <= b[j].leave.t ? a[i].leave : b[j].leave;
    if (enter.t < leave.t) out.push_back({enter, leave});
    if (a[i].leave.t <= b[j].leave.t)
      ++i;
    else
      ++j;
  }
}

template <typename T>
Hit<T> flipped(Hit<T> h) {
  h.normal = -h.normal;
  return h;
}

template <typename T>
void subtractSpans(const SpanList<T>& a, const SpanList<T>& b, SpanList<T>& out) {
  std::size_t j = 0;
  for (const Span<T>& s : a) {
    while (j < b.size() && b[j].leave.t <= s.enter.t) ++j;
    Hit<T> start = s.enter;
    bool alive = true;
    for (std::size_t k = j; k < b.size() && b[k].enter.t < s.leave.t; ++k) {
      if (b[k].enter.t > start.t) out.push_back({start, flipped(b[k].enter)});
      if (b[k].leave.t >= s.leave.t) {
        alive = false;
        break;
      }
      if (b[k].leave.t > start.t) start = flipped(b[k].leave);
    }
    if (alive && start.t < s.leave.t) out.push_back({start, s.leave});
  }
}

// Drops spans that do not overlap the open interval (tmin, tmax).
template <typename T>
void keepOverlapping(SpanList<T>& list, T tmin, T tmax) {
  std::size_t kept = 0;
  for (std::size_t n = 0; n < list.size(); ++n)
    if (list[n].leave.t > tmin && list[n].enter.t < tmax) list[kept++] = list[n];
  while (list.size() > kept) list.pop_back();
}

}  // namespace lattice
