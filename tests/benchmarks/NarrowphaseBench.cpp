// narrowphase_bench - how many box-box and circle-circle tests per nanosecond, written with
// branches (the lecture's early returns, &&) and without (every comparison computed, &).
// Each iteration tests 4,096 pairs of random shapes, about half of them overlapping, so the
// CPU cannot guess the branches. items_per_second / 1e9 = tests per nanosecond.
// The last two run the same box pairs as GameObjects through Collision's facade: with Hitbox's
// own table (the default argument) and with a table the caller built once; they should match.
#include "hitbox/geometry/Overlap.h"
#include "hitbox/objects/Collision.h"
#include "hitbox/objects/GameObject.h"
#include "hitbox/objects/ShapeTable.h"

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

namespace
{

constexpr std::size_t kPairs = 4096;

struct Boxes
{
    std::vector<float> minX, minY, maxX, maxY;
};

struct Circles
{
    std::vector<float> x, y, radius;
};

Boxes randomBoxes(unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> position(0.f, 60.f), side(4.f, 16.f);
    Boxes boxes;
    for (std::size_t i = 0; i < 2 * kPairs; ++i)
    {
        const float x = position(random), y = position(random);
        boxes.minX.push_back(x);
        boxes.minY.push_back(y);
        boxes.maxX.push_back(x + side(random));
        boxes.maxY.push_back(y + side(random));
    }
    return boxes;
}

Circles randomCircles(unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> position(0.f, 40.f), radius(2.f, 8.f);
    Circles circles;
    for (std::size_t i = 0; i < 2 * kPairs; ++i)
    {
        circles.x.push_back(position(random));
        circles.y.push_back(position(random));
        circles.radius.push_back(radius(random));
    }
    return circles;
}

// The lecture's test: return as soon as one axis separates them.
bool boxesOverlapBranchy(const Boxes& b, std::size_t i, std::size_t j)
{
    if (b.maxX[i] <= b.minX[j])
        return false;
    if (b.maxX[j] <= b.minX[i])
        return false;
    if (b.maxY[i] <= b.minY[j])
        return false;
    if (b.maxY[j] <= b.minY[i])
        return false;
    return true;
}

// All four comparisons, combined with & : no jumps, and the compiler can use SIMD.
bool boxesOverlapBranchFree(const Boxes& b, std::size_t i, std::size_t j)
{
    return (b.minX[i] < b.maxX[j]) & (b.minX[j] < b.maxX[i]) & (b.minY[i] < b.maxY[j]) &
           (b.minY[j] < b.maxY[i]);
}

bool circlesOverlapBranchy(const Circles& c, std::size_t i, std::size_t j)
{
    const float dx = c.x[i] - c.x[j];
    const float reach = c.radius[i] + c.radius[j];
    if (dx >= reach || dx <= -reach)
        return false; // too far apart on x alone: skip the multiplications
    const float dy = c.y[i] - c.y[j];
    if (dy >= reach || dy <= -reach)
        return false;
    return dx * dx + dy * dy < reach * reach;
}

bool circlesOverlapBranchFree(const Circles& c, std::size_t i, std::size_t j)
{
    const float dx = c.x[i] - c.x[j];
    const float dy = c.y[i] - c.y[j];
    const float reach = c.radius[i] + c.radius[j];
    return dx * dx + dy * dy < reach * reach;
}

template <typename Shapes, typename Test>
void runTests(benchmark::State& state, const Shapes& shapes, Test test)
{
    for (auto _ : state)
    {
        int hits = 0;
        for (std::size_t k = 0; k < kPairs; ++k)
            hits += test(shapes, 2 * k, 2 * k + 1);
        benchmark::DoNotOptimize(hits);
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kPairs));
}

void BoxBox_Branchy(benchmark::State& state)
{
    runTests(state, randomBoxes(1), boxesOverlapBranchy);
}
void BoxBox_BranchFree(benchmark::State& state)
{
    runTests(state, randomBoxes(1), boxesOverlapBranchFree);
}
void BoxBox_FrameworkBoxVsBox(benchmark::State& state)
{
    // hitbox::boxVsBox also rejects NaN and flips negative sizes: the safe, slower default.
    std::vector<hitbox::Box> boxes;
    const Boxes b = randomBoxes(1);
    for (std::size_t i = 0; i < b.minX.size(); ++i)
        boxes.push_back({b.minX[i], b.minY[i], b.maxX[i] - b.minX[i], b.maxY[i] - b.minY[i]});
    runTests(state, boxes,
             [](const std::vector<hitbox::Box>& all, std::size_t i, std::size_t j)
             { return hitbox::boxVsBox(all[i], all[j]); });
}
void CircleCircle_Branchy(benchmark::State& state)
{
    runTests(state, randomCircles(2), circlesOverlapBranchy);
}
void CircleCircle_BranchFree(benchmark::State& state)
{
    runTests(state, randomCircles(2), circlesOverlapBranchFree);
}
void CircleCircle_FrameworkCircleVsCircle(benchmark::State& state)
{
    std::vector<hitbox::Circle> circles;
    const Circles c = randomCircles(2);
    for (std::size_t i = 0; i < c.x.size(); ++i)
        circles.push_back({{c.x[i], c.y[i]}, c.radius[i]});
    runTests(state, circles,
             [](const std::vector<hitbox::Circle>& all, std::size_t i, std::size_t j)
             { return hitbox::circleVsCircle(all[i], all[j]); });
}

std::vector<hitbox::GameObject> boxObjects()
{
    const Boxes b = randomBoxes(1);
    std::vector<hitbox::GameObject> objects(b.minX.size());
    for (std::size_t i = 0; i < objects.size(); ++i)
    {
        objects[i].setPosition({b.minX[i], b.minY[i]});
        objects[i].setCollisionBox(0.f, 0.f, b.maxX[i] - b.minX[i], b.maxY[i] - b.minY[i]);
    }
    return objects;
}

std::vector<hitbox::GameObject*> addressesOf(std::vector<hitbox::GameObject>& objects)
{
    std::vector<hitbox::GameObject*> addresses;
    for (hitbox::GameObject& object : objects)
        addresses.push_back(&object);
    return addresses;
}

void BoxBox_CollisionStandardTable(benchmark::State& state)
{
    std::vector<hitbox::GameObject> objects = boxObjects();
    runTests(state, addressesOf(objects),
             [](const std::vector<hitbox::GameObject*>& all, std::size_t i, std::size_t j)
             {
                 return hitbox::Collision::getContact(all[i], hitbox::ShapeKind::Box, all[j],
                                                      hitbox::ShapeKind::Box)
                     .hit;
             });
}
void BoxBox_CollisionGivenTable(benchmark::State& state)
{
    std::vector<hitbox::GameObject> objects = boxObjects();
    const hitbox::ShapeTable table = hitbox::ShapeTable::standard();
    runTests(state, addressesOf(objects),
             [&table](const std::vector<hitbox::GameObject*>& all, std::size_t i, std::size_t j)
             {
                 return hitbox::Collision::getContact(all[i], hitbox::ShapeKind::Box, all[j],
                                                      hitbox::ShapeKind::Box, table)
                     .hit;
             });
}

} // namespace

BENCHMARK(BoxBox_Branchy);
BENCHMARK(BoxBox_BranchFree);
BENCHMARK(BoxBox_FrameworkBoxVsBox);
BENCHMARK(CircleCircle_Branchy);
BENCHMARK(CircleCircle_BranchFree);
BENCHMARK(CircleCircle_FrameworkCircleVsCircle);
BENCHMARK(BoxBox_CollisionStandardTable);
BENCHMARK(BoxBox_CollisionGivenTable);

BENCHMARK_MAIN();
