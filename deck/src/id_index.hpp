// SPDX-License-Identifier: GPL-3.0-or-later
// Map from user ids (node, element, object ids) to a payload index. Dense table when the
// ids are compact (the usual case: O(1) lookups for millions of node references), sorted
// vector with binary search otherwise. Duplicates are reported by build().
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace hbm::deck::detail {

class IdIndex {
 public:
  static constexpr std::uint32_t kNone = 0xffffffffu;

  void reserve(std::size_t n) { entries_.reserve(n); }
  void add(std::int64_t id, std::uint32_t payload) { entries_.emplace_back(id, payload); }

  // Builds the lookup; calls dup(id, first_payload, second_payload) for every repeat.
  template <class OnDuplicate>
  void build(OnDuplicate&& dup) {
    dense_.clear();
    if (entries_.empty()) return;
    std::int64_t lo = entries_.front().first, hi = lo;
    for (const auto& e : entries_) {
      lo = std::min(lo, e.first);
      hi = std::max(hi, e.first);
    }
    const std::uint64_t range = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo);
    if (range < 4 * entries_.size() + 1024) {
      base_ = lo;
      dense_.assign(range + 1, kNone);
      for (const auto& e : entries_) {
        std::uint32_t& slot = dense_[static_cast<std::size_t>(e.first - lo)];
        if (slot != kNone) {
          dup(e.first, slot, e.second);
        } else {
          slot = e.second;
        }
      }
      entries_.clear();
      entries_.shrink_to_fit();
      is_dense_ = true;
      return;
    }
    is_dense_ = false;
    std::stable_sort(entries_.begin(), entries_.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::size_t w = 0;
    for (std::size_t i = 0; i < entries_.size(); ++i) {
      if (w > 0 && entries_[w - 1].first == entries_[i].first) {
        dup(entries_[i].first, entries_[w - 1].second, entries_[i].second);
        continue;
      }
      entries_[w++] = entries_[i];
    }
    entries_.resize(w);
  }

  std::uint32_t find(std::int64_t id) const {
    if (is_dense_) {
      if (id < base_ || static_cast<std::uint64_t>(id - base_) >= dense_.size()) return kNone;
      return dense_[static_cast<std::size_t>(id - base_)];
    }
    auto it = std::lower_bound(entries_.begin(), entries_.end(), id,
                               [](const auto& e, std::int64_t v) { return e.first < v; });
    return (it != entries_.end() && it->first == id) ? it->second : kNone;
  }
  bool contains(std::int64_t id) const { return find(id) != kNone; }

 private:
  std::vector<std::pair<std::int64_t, std::uint32_t>> entries_;
  std::vector<std::uint32_t> dense_;
  std::int64_t base_ = 0;
  bool is_dense_ = false;
};

}  // namespace hbm::deck::detail
