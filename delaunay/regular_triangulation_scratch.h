// What RegularTriangulation's insertion (regular_triangulation.cpp) and its removal
// (regular_triangulation_removal.cpp) share: the working memory of the operations and the cell
// allocator. Internal: not part of the library's interface.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include <delpsc/kernel/large_array.h>

#include "regular_triangulation.h"
#include "small_map.h"

namespace delpsc::delaunay {

namespace detail {

constexpr std::uint8_t kInConflict = 1;     // cell mark: in the conflict region
constexpr std::uint8_t kNotInConflict = 2;  // cell mark: tested, not in conflict

/// A growable array of trivially copyable items for scratch lists: unlike std::vector it never
/// initialises its storage, and the hot loops append through a raw pointer with a local count
/// (which stays in a register even while byte-sized marks, which may alias anything, are
/// written) after reserving room for a burst of appends.
template <class T>
class ScratchList {
 public:
  void clear() { size_ = 0; }
  /// Makes room for `more` appends beyond the current size; returns the (possibly moved) data.
  T* reserve_more(std::size_t more) {
    if (size_ + more > capacity_) {
      const std::size_t capacity = std::max<std::size_t>(2 * (size_ + more), 64);
      auto data = std::make_unique_for_overwrite<T[]>(capacity);
      std::copy(data_.get(), data_.get() + size_, data.get());
      data_ = std::move(data);
      capacity_ = capacity;
    }
    return data_.get();
  }
  void set_size(std::size_t n) { size_ = n; }
  void push_back(const T& x) {
    reserve_more(1);
    data_[size_++] = x;
  }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  std::size_t capacity() const { return capacity_; }
  T* data() { return data_.get(); }
  const T* data() const { return data_.get(); }
  const T* begin() const { return data_.get(); }
  const T* end() const { return data_.get() + size_; }
  const T& operator[](std::size_t i) const { return data_[i]; }

 private:
  std::unique_ptr<T[]> data_;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

}  // namespace detail

/// Working memory of the operations, kept between calls so that an insertion allocates nothing
/// once the vectors have grown to the largest cavity seen.
struct RegularTriangulation::Scratch {
  kernel::LargeVector<std::uint8_t> cell_mark;  // by CellId; all zero between operations
  std::vector<std::uint32_t> local_id;          // by PointId; all zero between operations
  detail::ScratchList<CellId> conflict;         // conflict region, in discovery order
  detail::ScratchList<CellId> rejected;         // neighbours tested and found not in conflict
  detail::ScratchList<Facet> boundary;          // cavity boundary, as facets of conflict cells
  std::vector<CellId> created;                  // cells made by the current operation
  std::vector<PointId> interior;                // vertices made redundant by the current insertion
  std::vector<PointId> relocate;                // hidden points whose cell was destroyed
  std::vector<PointId> boundary_vertices;       // vertices of the cavity boundary; local id = rank + 1
  std::vector<std::array<std::uint32_t, 4>> created_local;  // local ids of each new cell's vertices
  std::vector<std::uint32_t> edge_table;        // directed boundary edge (local ids) -> new cell facet
  detail::SmallMap edges;                       // the same for cavities too large for the table

  // Removal.
  std::vector<CellId> star;                     // cells incident to the removed vertex
  std::vector<PointId> link_points;             // link vertex number (in `link`) -> PointId
  detail::SmallMap local_of;                    // PointId -> link vertex number
  detail::SmallMap outer_of;                    // hole boundary facet (oriented link key) -> outside facet
  std::vector<std::uint32_t> hole_outer;        // per hole cell and facet: outside facet, or none
  detail::SmallMap new_of_star;                 // flat removal: star cell -> its replacement
  std::vector<CellId> hole;                     // cells of `link` inside the hole
  std::vector<CellId> new_of;                   // cell of `link` -> new cell here
  std::vector<PointId> reinsert;                // hidden points of the star, inserted again
  std::unique_ptr<RegularTriangulation> link;   // regular triangulation of the link vertices
};

// Recycles the most recently freed slot (the cells of the last cavity, hot in cache and close in
// space to the next insertion), else appends. Here, inline, for both files' hot loops.
inline CellId RegularTriangulation::new_cell() {
  if (free_head_ == kNoCell) return append_cell();
  const CellId c = free_head_;
  free_head_ = cells_[c].n[0];
  --free_count_;
  return c;
}

}  // namespace delpsc::delaunay
