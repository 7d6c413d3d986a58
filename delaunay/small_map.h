// A small open-addressing hash map from 64-bit keys to 32-bit values, for the per-operation
// bookkeeping of the triangulation (cavity edges, link facets) and for numbering a large link's
// vertices in the disk condition (refine/link_shape.cpp). Clearing is O(1) (entries carry the
// epoch of the operation that wrote them), and the arrays are kept between operations, so a
// steady stream of insertions allocates nothing. Not part of the public interface.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <delpsc/kernel/large_array.h>

namespace delpsc::delaunay::detail {

class SmallMap {
 public:
  /// Empties the map and makes room for about `expected` entries (it grows beyond if needed).
  void reset(std::size_t expected) {
    std::size_t capacity = 16;
    while (capacity < 2 * expected) capacity <<= 1;
    if (capacity > keys_.size()) {
      keys_.assign(capacity, 0);
      values_.assign(capacity, 0);
      epochs_.assign(capacity, 0);
      epoch_ = 0;
    }
    set_shift();
    if (++epoch_ == 0) {  // wrapped: stale entries could look current
      epochs_.assign(epochs_.size(), 0);
      epoch_ = 1;
    }
    size_ = 0;
  }

  /// The value stored for key, or nullptr.
  const std::uint32_t* find(std::uint64_t key) const {
    for (std::size_t i = slot(key);; i = (i + 1) & mask_) {
      if (epochs_[i] != epoch_) return nullptr;
      if (keys_[i] == key) return &values_[i];
    }
  }

  /// Stores key -> value. Precondition: key is absent.
  void insert(std::uint64_t key, std::uint32_t value) {
    if (2 * (size_ + 1) > keys_.size()) grow();
    std::size_t i = slot(key);
    while (epochs_[i] == epoch_) i = (i + 1) & mask_;
    keys_[i] = key;
    values_[i] = value;
    epochs_[i] = epoch_;
    ++size_;
  }

  std::size_t size() const { return size_; }
  std::size_t memory_bytes() const { return keys_.capacity() * 16; }

 private:
  std::size_t slot(std::uint64_t key) const {
    return static_cast<std::size_t>((key * 0x9e3779b97f4a7c15ull) >> shift_);
  }
  void set_shift() {
    mask_ = keys_.size() - 1;
    shift_ = 64;
    for (std::size_t c = keys_.size(); c > 1; c >>= 1) --shift_;
  }
  void grow() {
    std::vector<std::uint64_t> keys;
    std::vector<std::uint32_t> values;
    for (std::size_t i = 0; i < keys_.size(); ++i)
      if (epochs_[i] == epoch_) {
        keys.push_back(keys_[i]);
        values.push_back(values_[i]);
      }
    const std::size_t capacity = 2 * (keys_.size() > 0 ? keys_.size() : 8);
    keys_.assign(capacity, 0);
    values_.assign(capacity, 0);
    epochs_.assign(capacity, 0);
    epoch_ = 1;
    set_shift();
    size_ = 0;
    for (std::size_t i = 0; i < keys.size(); ++i) insert(keys[i], values[i]);
  }

  kernel::LargeVector<std::uint64_t> keys_;
  kernel::LargeVector<std::uint32_t> values_;
  kernel::LargeVector<std::uint32_t> epochs_;
  std::uint32_t epoch_ = 0;
  std::size_t mask_ = 0;
  int shift_ = 64;
  std::size_t size_ = 0;
};

}  // namespace delpsc::delaunay::detail
