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

}  // namespace seaway
