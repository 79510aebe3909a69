// The queue a search uses, chosen in one place from the model's bounds on a step's cost
// (Model::bounds()): buckets when every step's key rises by at least a positive floor and the
// range needs few buckets; buckets with an overflow heap when a step has no upper cost but a
// usual one (a wait); a radix heap for other monotone keys; a 4-ary heap for keys that are not
// monotone (weighted A*); pooled chunks for rings of many sparse buckets.
#pragma once

#include "bucket_queue.hpp"
#include "chunked_bucket_queue.hpp"
#include "constants.hpp"
#include "cost_models.hpp"
#include "quaternary_heap.hpp"
#include "radix_heap.hpp"

namespace seaway {

enum class QueueKind { radix, buckets, chunked_buckets, overflow_buckets, quaternary };

struct QueueChoice {
  QueueKind kind = QueueKind::radix;
  double width = 0, span = 0;  // the bucket queues' bucket width and largest key rise
  double buckets() const { return buckets_needed(width, span); }
};

// Buckets of width `share` x min_rate x the shortest step (lengths count only for models priced
// per length) when a step's key rises by at most (max_rate + extra_rate) x the longest step +
// `extra`: with a scaled A* bound or a potential, `share` is the least share of a step's cost
// left in its reduced cost and `extra_rate` the most the bound can drop along a step.
inline QueueChoice choose_queue(const StepBounds& b, double shortest, double longest, double share,
                                double extra_rate = 0.0, double extra = 0.0) {
  const double rmin = b.per_length ? shortest : 1.0, rmax = b.per_length ? longest : 1.0;
  QueueChoice q;
  q.width = bucket_width_margin * share * b.min_rate * rmin;
  q.span = bucket_span_margin * (b.max_rate + extra_rate) * rmax + extra + 1e-300;
  if (q.width > 0 && q.span < inf && q.buckets() < max_buckets) {
    q.kind = QueueKind::buckets;
  } else if (q.width > 0 && b.usual_max_rate < inf) {  // no upper cost, but a usual one: overflow
    q.span = bucket_span_margin * (b.usual_max_rate + extra_rate) * rmax + extra + 1e-300;
    if (q.buckets() < max_buckets) q.kind = QueueKind::overflow_buckets;
  }
  return q;
}

// Calls f(queue) with a new queue of the chosen kind; the kinds a search cannot take are
// switched off (Heap4: the 4-ary heap, Chunked: the chunked buckets, Overflow: buckets with an
// overflow heap) and never instantiated.
template <bool Heap4, bool Chunked, bool Overflow = false, class F>
auto with_queue(const QueueChoice& q, F&& f) {
  if constexpr (Heap4)
    if (q.kind == QueueKind::quaternary) return f(QuaternaryHeap{});
  if constexpr (Overflow)
    if (q.kind == QueueKind::overflow_buckets) return f(OverflowBucketQueue(q.width, q.span));
  if constexpr (Chunked)
    if (q.kind == QueueKind::chunked_buckets) return f(ChunkedBucketQueue(q.width, q.span));
  if (q.kind == QueueKind::buckets || q.kind == QueueKind::chunked_buckets)
    return f(BucketQueue(q.width, q.span));
  return f(RadixHeap{});
}

}  // namespace seaway
