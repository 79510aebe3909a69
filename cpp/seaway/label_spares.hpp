// Search labels outlive the chart that made them: a new chart of the same size (seaway.route
// called again on a raster of the same shape, a season's charts) takes the labels a chart left
// instead of mapping new pages, whose first writes fault (a few microseconds each in a VM: about
// 100 faults, 0.3 ms, in a two-thread query on a 10^5-pixel chart). At most spare_label_bytes of
// their resident pages are kept, process-wide; the oldest go first.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "lazy_labels.hpp"

namespace seaway {

constexpr std::size_t spare_label_bytes = std::size_t(64) << 20;

namespace detail {
struct LabelSpares {
  std::mutex mutex;
  std::vector<std::unique_ptr<LazyLabels>> kept;  // oldest first
  std::size_t bytes = 0;                          // their resident pages
};
inline LabelSpares& label_spares() {
  static LabelSpares spares;
  return spares;
}
}  // namespace detail

// Labels for n pixels left by a chart that is gone, or null.
inline std::unique_ptr<LazyLabels> spare_labels(std::int64_t n) {
  detail::LabelSpares& s = detail::label_spares();
  std::lock_guard<std::mutex> lock(s.mutex);
  for (auto it = s.kept.begin(); it != s.kept.end(); ++it)
    if ((*it)->size() == n) {
      std::unique_ptr<LazyLabels> out = std::move(*it);
      s.kept.erase(it);
      s.bytes -= out->resident_bytes();
      return out;
    }
  return nullptr;
}

// Keeps the labels of a chart that goes away for the next chart of its size.
inline void keep_spare_labels(std::unique_ptr<LazyLabels> labels) {
  const std::size_t bytes = labels->resident_bytes();
  if (bytes > spare_label_bytes) return;  // unmapped here
  detail::LabelSpares& s = detail::label_spares();
  std::lock_guard<std::mutex> lock(s.mutex);
  s.kept.push_back(std::move(labels));
  s.bytes += bytes;
  while (s.bytes > spare_label_bytes) {
    s.bytes -= s.kept.front()->resident_bytes();
    s.kept.erase(s.kept.begin());
  }
}

// A chart's labels between its queries: two for the sides of a bidirectional search, three for
// the searches' bound caches (CachedBound). Each is kept with its pages while it holds at most
// 6 bytes per pixel (a cache: 2 bytes per pixel, or 16 MiB whatever the chart's size), else
// with its pages given back to the kernel; when the chart goes, they serve the next chart of
// its size (above).
class LabelPool {
 public:
  explicit LabelPool(std::int64_t n) : n_(n) {}
  ~LabelPool() {
    for (auto* pool : {&sides_, &caches_})
      for (auto& labels : *pool) keep_spare_labels(std::move(labels));
  }
  LabelPool(const LabelPool&) = delete;
  LabelPool& operator=(const LabelPool&) = delete;
  std::unique_ptr<LazyLabels> take(bool cache) {
    std::lock_guard<std::mutex> lock(mutex_);
    auto& pool = cache ? caches_ : sides_;
    if (pool.empty()) {
      std::unique_ptr<LazyLabels> spare = spare_labels(n_);  // left by a chart of this size
      return spare ? std::move(spare) : std::make_unique<LazyLabels>(n_);
    }
    std::unique_ptr<LazyLabels> out = std::move(pool.back());
    pool.pop_back();
    return out;
  }
  void give(std::unique_ptr<LazyLabels> labels, bool cache) {
    const std::size_t bytes = labels->resident_bytes(), n = std::size_t(n_);
    if (cache ? bytes > 2 * n && bytes > (std::size_t(16) << 20) : bytes > 6 * n) labels->release();
    std::lock_guard<std::mutex> lock(mutex_);
    auto& pool = cache ? caches_ : sides_;
    if (pool.size() < (cache ? 3u : 2u)) pool.push_back(std::move(labels));
  }

 private:
  std::int64_t n_;
  std::mutex mutex_;
  std::vector<std::unique_ptr<LazyLabels>> sides_, caches_;
};

// Labels borrowed from a chart's pool for one query, as the last search left them (the borrower
// clears them on its own thread), given back when the query ends.
class LabelLease {
 public:
  explicit LabelLease(LabelPool& pool, bool cache = false) : pool_(pool), cache_(cache), labels_(pool.take(cache)) {}
  ~LabelLease() { pool_.give(std::move(labels_), cache_); }
  LabelLease(const LabelLease&) = delete;
  LabelLease& operator=(const LabelLease&) = delete;
  LazyLabels& operator*() { return *labels_; }

 private:
  LabelPool& pool_;
  bool cache_;
  std::unique_ptr<LazyLabels> labels_;
};

}  // namespace seaway
