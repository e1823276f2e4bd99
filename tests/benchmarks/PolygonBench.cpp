// polygon_bench - the separating axis test between a square and an n-gon, as Hitbox runs it
// (polygonVsPolygon: walking support points, O(n + m)) and the way it ran before (every
// corner projected on every edge's axis, O((n + m)^2)). Same shapes, same answers; the
// ratio of the times is the point. Build and run in release:
//   cmake --preset release && cmake --build --preset release --target polygon_bench
//   build/release/tests/benchmarks/polygon_bench
#include "hitbox/geometry/Polygon.h"
#include "hitbox/geometry/Vec2.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

namespace
{

// A regular n-gon of radius 1000 round the origin, and a 20 x 10 square reaching 10 px in.
hitbox::Polygon wheel(int corners)
{
    hitbox::Polygon polygon;
    for (int k = 0; k < corners; ++k)
    {
        const double angle = 2.0 * hitbox::piDouble * k / corners;
        polygon.points.push_back({static_cast<float>(1000.0 * std::cos(angle)),
                                  static_cast<float>(1000.0 * std::sin(angle))});
    }
    return polygon;
}
const hitbox::Polygon square = hitbox::toPolygon(hitbox::Box(990.f, -5.f, 20.f, 10.f));

// The old way: project every corner of both polygons on the axis of every edge of both, and
// keep the least overlap (0 when some axis separates them).
float leastOverlapProjectingEveryCorner(const hitbox::Polygon& a, const hitbox::Polygon& b)
{
    float least = HUGE_VALF;
    for (const hitbox::Polygon* owner : {&a, &b})
        for (std::size_t i = 0; i < owner->points.size(); ++i)
        {
            const hitbox::Vec2 from = owner->points[i];
            const hitbox::Vec2 to = owner->points[(i + 1) % owner->points.size()];
            const hitbox::Vec2 axis = hitbox::perpendicular(to - from);
            float minA = HUGE_VALF, maxA = -HUGE_VALF, minB = HUGE_VALF, maxB = -HUGE_VALF;
            for (hitbox::Vec2 p : a.points)
            {
                minA = std::fmin(minA, hitbox::dot(p, axis));
                maxA = std::fmax(maxA, hitbox::dot(p, axis));
            }
            for (hitbox::Vec2 p : b.points)
            {
                minB = std::fmin(minB, hitbox::dot(p, axis));
                maxB = std::fmax(maxB, hitbox::dot(p, axis));
            }
            const float overlap = std::fmin(maxB - minA, maxA - minB) / hitbox::length(axis);
            if (!(overlap > 0.f))
                return 0.f;
            least = std::fmin(least, overlap);
        }
    return least;
}

void SquareVsNGon_WalkingSupportPoints(benchmark::State& state)
{
    const hitbox::Polygon polygon = wheel(static_cast<int>(state.range(0)));
    for (auto _ : state)
        benchmark::DoNotOptimize(hitbox::polygonVsPolygon(square, polygon));
    state.counters["depth"] = hitbox::polygonVsPolygon(square, polygon).depth;
}

void SquareVsNGon_ProjectEveryCorner(benchmark::State& state)
{
    const hitbox::Polygon polygon = wheel(static_cast<int>(state.range(0)));
    for (auto _ : state)
        benchmark::DoNotOptimize(leastOverlapProjectingEveryCorner(square, polygon));
    state.counters["depth"] = leastOverlapProjectingEveryCorner(square, polygon);
}

} // namespace

BENCHMARK(SquareVsNGon_WalkingSupportPoints)
    ->RangeMultiplier(10)
    ->Range(10, 100000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(SquareVsNGon_ProjectEveryCorner)
    ->RangeMultiplier(10)
    ->Range(10, 10000)
    ->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
