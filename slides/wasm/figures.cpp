// figures.cpp - the slides' interactive figures ask Hitbox's own geometry for every answer.
//
// Compiled to WebAssembly (slides/wasm/build.sh, emcc) for the decks, and natively for the
// test that checks what a figure shows (slides/wasm/answers.cpp). Each function takes the
// figure's shapes as plain numbers, calls the geometry functions the slides teach, and writes
// its answer into `out` (floats; true = 1, false = 0), in the order its comment gives.
// The JavaScript only draws what these return (slides/interactive/figures.js).
#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Polygon.h"
#include "hitbox/geometry/Sweep.h"

#include <cmath>
#include <limits>

#ifdef __EMSCRIPTEN__
#include <emscripten.h>
#define FIGURE_ANSWER extern "C" EMSCRIPTEN_KEEPALIVE
#else
#define FIGURE_ANSWER extern "C"
#endif

namespace
{

constexpr float infinity = std::numeric_limits<float>::infinity();

// One of the edge rule's comparisons on its own, `low < high`: spansOverlap against a span
// that reaches to infinity, whose other comparison is always true. The figures show the
// rule's own comparisons, so they change if the rule (Shapes.h) ever does.
float isBefore(float low, float high)
{
    return hitbox::spansOverlap(low, infinity, -infinity, high) ? 1.f : 0.f;
}

float flag(bool value)
{
    return value ? 1.f : 0.f;
}

// How far the figure's ray is extended both ways to stand for the whole line through S and E:
// far beyond the drawing, yet a float keeps its times to about 1/10000.
constexpr float lineReach = 1000.f;

// Where the whole line through start and end enters and leaves `box`, in the ray's own time
// (0 at start, 1 at end): segmentVsBox on the line cut off at -lineReach and +lineReach, run
// forwards for the entry and backwards for the exit. false when the line misses the box
// (touching only is a miss: segmentVsBox's edge rule). Entry -lineReach / exit +lineReach
// mean "inside for the whole line" (a ray along a slab).
bool lineTimes(hitbox::Vec2 start, hitbox::Vec2 end, const hitbox::Box& box, float& enter,
               float& exit)
{
    const hitbox::Vec2 move = end - start;
    const hitbox::Vec2 from = start - move * lineReach;
    const hitbox::Vec2 to = start + move * lineReach;
    const hitbox::Hit forwards = hitbox::segmentVsBox(from, to, box);
    const hitbox::Hit backwards = hitbox::segmentVsBox(to, from, box);
    if (!forwards.hit || !backwards.hit)
        return false;
    enter = -lineReach + forwards.time * 2.f * lineReach;
    exit = lineReach - backwards.time * 2.f * lineReach;
    return true;
}

} // namespace

// Two boxes. out: [A.left < B.right, B.left < A.right, A.top < B.bottom, B.top < A.bottom,
// boxVsBox, push-out normal x, y, depth] (boxVsBoxContact: moving A by normal * depth
// separates them).
FIGURE_ANSWER void boxesAnswer(float aLeft, float aTop, float aWidth, float aHeight, float bLeft,
                               float bTop, float bWidth, float bHeight, float* out)
{
    const hitbox::Box a(aLeft, aTop, aWidth, aHeight);
    const hitbox::Box b(bLeft, bTop, bWidth, bHeight);
    out[0] = isBefore(a.left, hitbox::rightOf(b));
    out[1] = isBefore(b.left, hitbox::rightOf(a));
    out[2] = isBefore(a.top, hitbox::bottomOf(b));
    out[3] = isBefore(b.top, hitbox::bottomOf(a));
    out[4] = flag(hitbox::boxVsBox(a, b));
    const hitbox::Contact contact = hitbox::boxVsBoxContact(a, b);
    out[5] = contact.normal.x;
    out[6] = contact.normal.y;
    out[7] = contact.depth;
}

// A point and a box. out: [left < x, x < right, top < y, y < bottom, pointInBox].
FIGURE_ANSWER void pointInBoxAnswer(float x, float y, float left, float top, float width,
                                    float height, float* out)
{
    const hitbox::Box box(left, top, width, height);
    out[0] = isBefore(box.left, x);
    out[1] = isBefore(x, hitbox::rightOf(box));
    out[2] = isBefore(box.top, y);
    out[3] = isBefore(y, hitbox::bottomOf(box));
    out[4] = flag(hitbox::pointInBox({x, y}, box));
}

// Two circles. out: [distance squared, (radius A + radius B) squared, circleVsCircle,
// push-out normal x, y, depth] (circleVsCircleContact).
FIGURE_ANSWER void circlesAnswer(float aX, float aY, float aRadius, float bX, float bY,
                                 float bRadius, float* out)
{
    const hitbox::Circle a{{aX, aY}, aRadius};
    const hitbox::Circle b{{bX, bY}, bRadius};
    const hitbox::Vec2 between = a.center - b.center;
    const float reach = a.radius + b.radius;
    out[0] = hitbox::dot(between, between);
    out[1] = reach * reach;
    out[2] = flag(hitbox::circleVsCircle(a, b));
    const hitbox::Contact contact = hitbox::circleVsCircleContact(a, b);
    out[3] = contact.normal.x;
    out[4] = contact.normal.y;
    out[5] = contact.depth;
}

// Two rotated boxes (centre, half size, angle in degrees clockwise). out: [separated, axis x,
// axis y, gap (minus the overlap when not separated)] from findSeparatingAxis; [4..11] A's
// corners and [12..19] B's (x, y each); [20, 21] A's shadow on the axis (lowest and highest
// point along it) and [22, 23] B's.
FIGURE_ANSWER void orientedBoxesAnswer(float aX, float aY, float aHalfWidth, float aHalfHeight,
                                       float aAngle, float bX, float bY, float bHalfWidth,
                                       float bHalfHeight, float bAngle, float* out)
{
    const hitbox::Polygon a =
        hitbox::toPolygon(hitbox::OrientedBox{{aX, aY}, {aHalfWidth, aHalfHeight}, aAngle});
    const hitbox::Polygon b =
        hitbox::toPolygon(hitbox::OrientedBox{{bX, bY}, {bHalfWidth, bHalfHeight}, bAngle});
    const hitbox::AxisReport report = hitbox::findSeparatingAxis(a, b);
    out[0] = flag(report.separated);
    out[1] = report.axis.x;
    out[2] = report.axis.y;
    out[3] = report.gap;
    int next = 4;
    for (const hitbox::Polygon* box : {&a, &b})
        for (hitbox::Vec2 corner : box->points)
        {
            out[next++] = corner.x;
            out[next++] = corner.y;
        }
    // The shadow of each box: how far along the axis its corners reach.
    for (const hitbox::Polygon* box : {&a, &b})
    {
        float lowest = infinity;
        float highest = -infinity;
        for (hitbox::Vec2 corner : box->points)
        {
            const float along = hitbox::dot(corner, report.axis);
            lowest = std::fmin(lowest, along);
            highest = std::fmax(highest, along);
        }
        out[next++] = lowest;
        out[next++] = highest;
    }
}

// A ray (the segment from start to end) against a box, by the slab method (segmentVsBox).
// out: [hit, near time, started inside, normal x, y, far time]. The far time, where the ray
// leaves the box, is the same test run backwards from the end: 1 - its near time. When the
// end is inside the box the ray has not left yet: far time -1.
// On a miss, the slab method's times for the whole line: [6] 1 when the line crosses the box,
// [7] its near and [8] far time (outside 0..1: the box is before S or after E); and each
// slab's own entry and exit, [9] 1 and [10], [11] for the x slab, [12] 1 and [13], [14] for the
// y slab (0: the line runs beside that slab and never enters it); when the line misses, the
// x and y stretches do not overlap.
FIGURE_ANSWER void rayAnswer(float startX, float startY, float endX, float endY, float left,
                             float top, float width, float height, float* out)
{
    const hitbox::Box box(left, top, width, height);
    const hitbox::Hit forwards = hitbox::segmentVsBox({startX, startY}, {endX, endY}, box);
    const hitbox::Hit backwards = hitbox::segmentVsBox({endX, endY}, {startX, startY}, box);
    out[0] = flag(forwards.hit);
    out[1] = forwards.time;
    out[2] = flag(forwards.startedInside);
    out[3] = forwards.normal.x;
    out[4] = forwards.normal.y;
    out[5] = !forwards.hit ? 0.f : backwards.startedInside ? -1.f : 1.f - backwards.time;
    if (forwards.hit)
        return;
    const hitbox::Vec2 start(startX, startY);
    const hitbox::Vec2 end(endX, endY);
    out[6] = flag(lineTimes(start, end, box, out[7], out[8]));
    // The slabs: the box's x range over every y, and its y range over every x.
    const float everywhere = 1e6f;
    const hitbox::Box xSlab(left, -everywhere, width, 2.f * everywhere);
    const hitbox::Box ySlab(-everywhere, top, 2.f * everywhere, height);
    out[9] = flag(lineTimes(start, end, xSlab, out[10], out[11]));
    out[12] = flag(lineTimes(start, end, ySlab, out[13], out[14]));
}

// A box moving by (moveX, moveY) this step against a wall (sweepBoxVsBox). out: [hit, time of
// impact, started inside, normal x, y].
FIGURE_ANSWER void sweptBoxAnswer(float left, float top, float width, float height, float moveX,
                                  float moveY, float wallLeft, float wallTop, float wallWidth,
                                  float wallHeight, float* out)
{
    const hitbox::Hit hit =
        hitbox::sweepBoxVsBox(hitbox::Box(left, top, width, height), {moveX, moveY},
                              hitbox::Box(wallLeft, wallTop, wallWidth, wallHeight));
    out[0] = flag(hit.hit);
    out[1] = hit.time;
    out[2] = flag(hit.startedInside);
    out[3] = hit.normal.x;
    out[4] = hit.normal.y;
}
