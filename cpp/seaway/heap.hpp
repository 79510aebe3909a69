// Priority queues for the searches, all with lazy deletion: a pixel whose cost improves is
// pushed again; its best entry pops first and later ones are skipped because the pixel is
// closed by then. They need no per-pixel position array and hold only the frontier.
//  - RadixHeap: for monotone keys (Dijkstra, and A* with a consistent bound): amortised O(1)
//    push, cheap pops; non-negative doubles order like their bit patterns.
//  - BucketQueue: for Dijkstra when every step costs at least `width` > 0: pixels whose keys
//    share a bucket [k*width, (k+1)*width) cannot improve each other, so a bucket may be
//    emptied in any order and the labels stay exact (Dial's algorithm on real keys).
//  - ChunkedBucketQueue: the same, with buckets in pooled chunks (for rings of many buckets).
//  - OverflowBucketQueue: the same, for steps with no upper cost (a wait for the ice to open):
//    keys beyond the ring wait in a heap until the scan reaches their bucket.
//  - QuaternaryHeap: a 4-ary heap for keys that are not monotone (weighted A*).
// This header holds their shared entry; queue_choice.hpp picks one for a search.
#pragma once

#include <cstdint>

namespace seaway {

struct HeapEntry {
  double key;  // priority: cost so far (+ A* bound)
  std::uint32_t id;
};

}  // namespace seaway
