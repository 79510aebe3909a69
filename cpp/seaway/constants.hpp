// The engine's numbers, in one place: physical constants, and the tuning constants the
// searches share (queue choice, polling).
#pragma once

#include <cstdint>
#include <limits>

namespace seaway {

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double pi = 3.14159265358979323846;
constexpr double deg = pi / 180.0;
constexpr double earth_radius_km = 6371.0088;  // IUGG mean Earth radius
constexpr double km_per_nm = 1.852;
constexpr double knots_per_ms = 3600.0 / 1852.0;

// A pixel's predecessor step when it has none (the start, or not reached).
constexpr std::uint8_t no_pred = 255;

// Every search publishes its progress and checks for cancellation once per this many settled
// pixels (a power of two: the test is a mask).
constexpr std::int64_t poll_every = 4096;

// A bucket queue is used when it needs fewer buckets than this; a ring of more than
// chunked_above buckets keeps them in pooled chunks (ChunkedBucketQueue).
constexpr double max_buckets = 65536;
constexpr double chunked_above = 4096;
// One-way A* (buckets a small share of a step wide) keeps its buckets in pooled chunks on charts
// of at most this many pixels: a vector per bucket costs allocations in every bucket a query
// fills. Prepared A*, CPU: CIS chart (180,000 pixels) 2-3 x faster, DMI (1.08 M) 1.4-1.6 x,
// 10^5-pixel charts 1.5 x, the game map (1 M) alike; the maze (1.44 M, costs 1-5) 13-20 % slower
// (auto takes bidirectional search there); on 4.4 M pixels the vectors, reused as the ring turns,
// were 5-10 % faster on voyages of millions of pixels.
constexpr std::int64_t chunked_astar_pixels = std::int64_t(1) << 21;
// Bucket width and span are taken a hair inside the step-cost bounds against their rounding.
constexpr double bucket_width_margin = 0.999999, bucket_span_margin = 1.000001;
// Share of the A* bound given up so that A* can use the bucket queue; 0.05 settled the fewest
// pixels per second on the benchmark charts (0.02 to 0.25 tried).
constexpr double astar_bucket_eps = 0.05;

}  // namespace seaway
