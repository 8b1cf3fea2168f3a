// One value per set of surfaces in the process, computed once and shared while anyone holds it:
// a crowd of humans of one body and outfit calibrates and judges its surfaces once, and humans
// coming and going do not redo it. Keyed by the control points of every patch of every surface.
// A cache made with `retained` > 0 also keeps that many of the values it made last alive when
// nobody holds them: a display rebuilding every human (a property changed) finds them again.
#pragma once

#include <algorithm>
#include <cstddef>
#include <deque>
#include <memory>
#include <mutex>
#include <vector>

#include "dressed_human/core/surfaces/bezier_patch.h"

namespace dressed_human {

template <typename Value>
class PatchKeyedCache {
 public:
  explicit PatchKeyedCache(std::size_t retained = 0) : retained_(retained) {}

  // The value for `surfaces`: the one still held somewhere, or make() (a shared_ptr to a new
  // value), called under the cache's lock so two callers never compute the same value.
  template <typename Make>
  std::shared_ptr<const Value> obtain(const std::vector<const std::vector<BezierPatch>*>& surfaces, Make make) {
    std::lock_guard<std::mutex> lock(mutex_);
    entries_.erase(std::remove_if(entries_.begin(), entries_.end(), [](const Entry& e) { return e.value.expired(); }),
                   entries_.end());
    for (const Entry& entry : entries_) {
      if (!same(entry.surfaces, surfaces)) continue;
      if (std::shared_ptr<const Value> value = entry.value.lock()) return value;
    }
    std::shared_ptr<const Value> value = make();
    Entry entry;
    for (const std::vector<BezierPatch>* surface : surfaces) entry.surfaces.push_back(*surface);
    entry.value = value;
    entries_.push_back(std::move(entry));
    if (retained_ > 0) {
      recent_.push_back(value);
      if (recent_.size() > retained_) recent_.pop_front();
    }
    return value;
  }

 private:
  struct Entry {
    std::vector<std::vector<BezierPatch>> surfaces;
    std::weak_ptr<const Value> value;
  };
  static bool same(const std::vector<std::vector<BezierPatch>>& held,
                   const std::vector<const std::vector<BezierPatch>*>& asked) {
    if (held.size() != asked.size()) return false;
    for (std::size_t s = 0; s < held.size(); ++s) {
      if (!std::equal(
              held[s].begin(), held[s].end(), asked[s]->begin(), asked[s]->end(),
              [](const BezierPatch& a, const BezierPatch& b) { return a.controlPoints() == b.controlPoints(); })) {
        return false;
      }
    }
    return true;
  }
  std::mutex mutex_;
  std::vector<Entry> entries_;
  std::size_t retained_;
  std::deque<std::shared_ptr<const Value>> recent_;  // the last `retained_` values made
};

}  // namespace dressed_human
