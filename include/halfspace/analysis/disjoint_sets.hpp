#pragma once
// Union-find over cell indices (path halving, union by size): the contact
// clusters' labelling, on one grid and joined across slab boundaries.

#include <cstddef>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace halfspace::analysis {

class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n), size_(n, 1) { std::iota(parent_.begin(), parent_.end(), 0); }

  // A new set standing for `size` elements; its index.
  std::size_t add(std::int64_t size) {
    parent_.push_back(parent_.size());
    size_.push_back(size);
    return parent_.size() - 1;
  }
  // `count` more elements in a's set.
  void grow(std::size_t a, std::int64_t count) { size_[find(a)] += count; }
  std::size_t count() const { return parent_.size(); }

  std::size_t find(std::size_t a) {
    while (parent_[a] != a) {
      parent_[a] = parent_[parent_[a]];
      a = parent_[a];
    }
    return a;
  }

  void unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
  }

  std::int64_t size_of_root(std::size_t root) const { return size_[root]; }

 private:
  std::vector<std::size_t> parent_;
  std::vector<std::int64_t> size_;
};

}  // namespace halfspace::analysis
