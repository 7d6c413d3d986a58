// Per-vertex lists of restricted-facet incidences (restricted_facets.h), in one flat array.
//
// A surface vertex has ~6 restricted facets and a vertex on a curve or at a corner a few dozen
// at most, so each vertex gets kInline slots in one array indexed by vertex; a list that
// outgrows them moves to a side table. One std::vector per vertex, as before, cost a heap block
// each (~54,000 on the cube at 0.456%, each first touched by a page fault) and scattered the
// lists the disk condition reads over the heap.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include <delpsc/kernel/large_array.h>

namespace delpsc::refine {

/// The lists of T by vertex id. T is trivially copyable; order within a list is not kept by
/// erase(). Ids are dense (the triangulation's PointIds).
template <class T>
class IncidenceLists {
 public:
  static constexpr std::uint32_t kInline = 8;

  /// v's list; empty for a vertex never added to. O(1).
  std::span<const T> operator[](std::uint32_t v) const {
    if (v >= count_.size()) return {};
    if (count_[v] == kSpilled) return spilled_.at(v);
    return {inline_.data() + std::size_t{v} * kInline, count_[v]};
  }

  /// Room for vertices [0, n) without moving the lists (the inline slots are allocated, not
  /// touched: a block of huge pages is faulted in only where written). O(1) when it fits.
  void reserve(std::size_t n) {
    count_.reserve(n);
    inline_.reserve(n * kInline);
  }

  /// Appends x to v's list. Amortised O(1).
  void push(std::uint32_t v, const T& x) {
    if (v >= count_.size()) grow(v);
    std::uint8_t& n = count_[v];
    if (n == kSpilled) {
      spilled_[v].push_back(x);
      return;
    }
    T* const block = inline_.data() + std::size_t{v} * kInline;
    if (n < kInline) {
      block[n++] = x;
      return;
    }
    std::vector<T>& list = spilled_[v];
    list.assign(block, block + kInline);
    list.push_back(x);
    n = kSpilled;
  }

  /// Removes the first element of v's list for which `match` is true (precondition: there is
  /// one), moving the last element into its place. O(length of the list).
  template <class Match>
  void erase_first(std::uint32_t v, Match match) {
    std::uint8_t& n = count_[v];
    if (n == kSpilled) {
      std::vector<T>& list = spilled_.at(v);
      for (std::size_t i = 0;; ++i)
        if (match(list[i])) {
          list[i] = list.back();
          list.pop_back();
          break;
        }
      if (list.size() <= kInline / 2) {  // back inline, with room to grow again
        std::copy(list.begin(), list.end(), inline_.data() + std::size_t{v} * kInline);
        n = static_cast<std::uint8_t>(list.size());
        spilled_.erase(v);
      }
      return;
    }
    T* const block = inline_.data() + std::size_t{v} * kInline;
    for (std::uint32_t i = 0;; ++i)
      if (match(block[i])) {
        block[i] = block[--n];
        return;
      }
  }

 private:
  static constexpr std::uint8_t kSpilled = 0xff;

  // Exactly to v: the vector's own growth keeps appends amortised O(1), and only the slots
  // used are zero-filled (touched) - with reserve() beforehand, nothing is copied either.
  void grow(std::uint32_t v) {
    count_.resize(std::size_t{v} + 1, 0);
    inline_.resize((std::size_t{v} + 1) * kInline);
  }

  kernel::LargeVector<T> inline_;         // kInline slots per vertex
  kernel::LargeVector<std::uint8_t> count_;  // per vertex: length, or kSpilled
  std::unordered_map<std::uint32_t, std::vector<T>> spilled_;
};

}  // namespace delpsc::refine
