// Grading tests of lab 11 (Pong). Each suite is named after the task it checks; README.md
// lists them. Everything runs with no window, one fixed step at a time, scripted.
//
// One mistake costs one task: each task's tests call that task's function, or set the state
// up directly, and never rely on another task's code. Where a test plays a whole match it
// checks only what its own task decides (the ball stays between the walls whatever the
// paddles do). The numbers come from Court.h, so the tests pass for any sensible values.
#include "labs/LabTesting.h"

#include "Ball.h"
#include "Court.h"
#include "Paddle.h"
#include "PongLevel.h"

#include "hitbox/app/App.h"
#include "hitbox/app/Input.h"
#include "hitbox/geometry/Sweep.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace
{

constexpr float dt = hitbox::stepSeconds;
const float courtMiddleY = (court.top + court.bottom) / 2.f;
const float courtMiddleX = (court.left + court.right) / 2.f;

hitbox::Box boxOf(const hitbox::GameObject& object)
{
    return hitbox::toBox(object.getCollisionBox());
}

float degreesFromHorizontal(sf::Vector2f velocity)
{
    return std::atan2(velocity.y, std::abs(velocity.x)) * 180.f / hitbox::pi;
}

float speedOf(sf::Vector2f velocity)
{
    return std::hypot(velocity.x, velocity.y);
}

// A ball that records every paddle hit and turns round flat, so the tests of task 5 check
// the sweep alone, whatever task 3's collisionResponse does.
class RecordingBall : public Ball
{
public:
    void collisionResponse(hitbox::GameObject* other) override
    {
        hits.push_back(other);
        const float away = getPosition().x < other->getPosition().x ? -1.f : 1.f;
        velocity = {away * std::abs(velocity.x), velocity.y};
    }
    std::vector<hitbox::GameObject*> hits;
};

// The two paddles where the level puts them.
struct Paddles
{
    Paddle left{court.left + paddleInset + paddleWidth / 2.f};
    Paddle right{court.right - paddleInset - paddleWidth / 2.f};
};

// Did the ball, moving from `before` by `move`, meet the front face of `paddle` (which moves
// by `paddleMove`) during the step? The framework's own sweep decides. `front` is the
// direction the face looks: +1 for the left paddle, -1 for the right one.
bool shouldHitFace(const hitbox::Box& before, sf::Vector2f move, const hitbox::Box& paddle,
                   sf::Vector2f paddleMove, float front)
{
    const hitbox::Hit hit = hitbox::sweepBoxVsMovingBox(before, hitbox::toVec2(move), paddle,
                                                        hitbox::toVec2(paddleMove));
    return hit && !hit.startedInside && hit.normal.x == front;
}

} // namespace

// --- Task 1 --------------------------------------------------------------------------

TEST(Task1MovePaddlesWithinTheCourt, MovesAtPaddleSpeedInTheMiddle)
{
    const Paddle paddle(100.f);
    EXPECT_NEAR(paddle.moveWithinCourt(1.f, dt).y, paddleSpeed * dt, 1e-4f);
    EXPECT_NEAR(paddle.moveWithinCourt(-1.f, dt).y, -paddleSpeed * dt, 1e-4f);
    EXPECT_EQ(paddle.moveWithinCourt(0.f, dt).y, 0.f);
    EXPECT_EQ(paddle.moveWithinCourt(1.f, dt).x, 0.f) << "a paddle moves up and down only";
    EXPECT_NEAR(paddle.moveWithinCourt(0.5f, dt).y, 0.5f * paddleSpeed * dt, 1e-4f)
        << "half a direction, half the speed (the computer steers this way)";
}

TEST(Task1MovePaddlesWithinTheCourt, ADirectionBeyondOneIsFullSpeed)
{
    const Paddle paddle(100.f);
    EXPECT_NEAR(paddle.moveWithinCourt(5.f, dt).y, paddleSpeed * dt, 1e-4f);
    EXPECT_NEAR(paddle.moveWithinCourt(-5.f, dt).y, -paddleSpeed * dt, 1e-4f);
}

TEST(Task1MovePaddlesWithinTheCourt, HeldUpItStopsTouchingTheTopNeverPast)
{
    Paddle paddle(100.f);
    const long long steps =
        static_cast<long long>((court.bottom - court.top) / (paddleSpeed * dt)) + 20;
    for (long long step = 0; step < steps; ++step)
    {
        paddle.move(paddle.moveWithinCourt(-1.f, dt));
        ASSERT_GE(boxOf(paddle).top, court.top) << "the paddle went past the top at step " << step;
    }
    EXPECT_NEAR(boxOf(paddle).top, court.top, 1e-3f)
        << "held up long enough, the paddle reaches the top edge (touching is allowed)";
}

TEST(Task1MovePaddlesWithinTheCourt, HeldDownItStopsTouchingTheBottomNeverPast)
{
    Paddle paddle(1000.f);
    const long long steps =
        static_cast<long long>((court.bottom - court.top) / (paddleSpeed * dt)) + 20;
    for (long long step = 0; step < steps; ++step)
    {
        paddle.move(paddle.moveWithinCourt(3.f, dt));
        ASSERT_LE(hitbox::bottomOf(boxOf(paddle)), court.bottom)
            << "the paddle went past the bottom at step " << step;
    }
    EXPECT_NEAR(hitbox::bottomOf(boxOf(paddle)), court.bottom, 1e-3f);
}

TEST(Task1MovePaddlesWithinTheCourt, TouchingAnEdgeItCanStillMoveAway)
{
    Paddle paddle(100.f);
    paddle.setPosition({100.f, court.top + paddleHeight / 2.f}); // touching the top
    EXPECT_EQ(paddle.moveWithinCourt(-1.f, dt).y, 0.f) << "no further up";
    EXPECT_NEAR(paddle.moveWithinCourt(1.f, dt).y, paddleSpeed * dt, 1e-4f) << "but down, yes";
    paddle.setPosition({100.f, court.bottom - paddleHeight / 2.f}); // touching the bottom
    EXPECT_EQ(paddle.moveWithinCourt(1.f, dt).y, 0.f) << "no further down";
    EXPECT_NEAR(paddle.moveWithinCourt(-1.f, dt).y, -paddleSpeed * dt, 1e-4f) << "but up, yes";
}

// --- Task 2 --------------------------------------------------------------------------

TEST(Task2BounceOffTopAndBottomWalls, PastTheTopItIsPutBackAndSentDown)
{
    Ball ball;
    ball.placeAt({500.f, court.top + ballSize / 2.f - 5.f}, {300.f, -200.f});
    EXPECT_TRUE(ball.bounceOffWalls());
    // Back against the wall, or mirrored by the 5 pixels it was past: both are fine.
    EXPECT_GE(boxOf(ball).top, court.top) << "put back inside the court";
    EXPECT_LE(boxOf(ball).top, court.top + 5.001f) << "put back against the top wall";
    EXPECT_VEC_NEAR(ball.getVelocity(), sf::Vector2f(300.f, 200.f), 1e-3f);
    EXPECT_FLOAT_EQ(ball.getPosition().x, 500.f) << "put back up or down only, not sideways";
}

TEST(Task2BounceOffTopAndBottomWalls, PastTheBottomItIsPutBackAndSentUp)
{
    Ball ball;
    ball.placeAt({500.f, court.bottom - ballSize / 2.f + 5.f}, {-300.f, 200.f});
    EXPECT_TRUE(ball.bounceOffWalls());
    EXPECT_LE(hitbox::bottomOf(boxOf(ball)), court.bottom) << "put back inside the court";
    EXPECT_GE(hitbox::bottomOf(boxOf(ball)), court.bottom - 5.001f)
        << "put back against the bottom wall";
    EXPECT_VEC_NEAR(ball.getVelocity(), sf::Vector2f(-300.f, -200.f), 1e-3f);
    EXPECT_FLOAT_EQ(ball.getPosition().x, 500.f) << "put back up or down only, not sideways";
}

TEST(Task2BounceOffTopAndBottomWalls, TouchingAWallIsNoBounce)
{
    Ball ball;
    for (const sf::Vector2f velocity : {sf::Vector2f(300.f, 0.f), sf::Vector2f(300.f, -200.f)})
    {
        ball.placeAt({500.f, court.top + ballSize / 2.f}, velocity); // touching the top
        EXPECT_FALSE(ball.bounceOffWalls()) << "touching is inside the court";
        EXPECT_VEC_NEAR(ball.getVelocity(), velocity, 0.f);
        EXPECT_NEAR(boxOf(ball).top, court.top, 1e-3f);
        ball.placeAt({500.f, court.bottom - ballSize / 2.f}, -velocity); // touching the bottom
        EXPECT_FALSE(ball.bounceOffWalls()) << "touching is inside the court";
        EXPECT_VEC_NEAR(ball.getVelocity(), -velocity, 0.f);
    }
}

TEST(Task2BounceOffTopAndBottomWalls, ABallOnItsWayBackIsNotTurnedIntoTheWall)
{
    Ball ball;
    ball.placeAt({500.f, court.top + ballSize / 2.f - 3.f}, {300.f, 200.f}); // moving down
    ball.bounceOffWalls();
    EXPECT_GT(ball.getVelocity().y, 0.f) << "still moving down, away from the top wall";
    ball.placeAt({500.f, court.bottom - ballSize / 2.f + 3.f}, {300.f, -200.f});
    ball.bounceOffWalls();
    EXPECT_LT(ball.getVelocity().y, 0.f) << "still moving up, away from the bottom wall";
}

TEST(Task2BounceOffTopAndBottomWalls, OverALongRallyTheBallNeverLeavesBetweenTheWalls)
{
    // A minute of play with the walls alone: the test moves the ball itself and turns it round
    // at the goal lines (so no other task's code plays a part), and sends a steep fast ball
    // now and then. After every step's bounceOffWalls the ball is between the walls.
    Ball ball;
    std::mt19937 random(11);
    std::uniform_real_distribution<float> steep(1000.f, 3000.f);
    ball.placeAt({courtMiddleX, courtMiddleY}, {ballSpeed, ballSpeed / 2.f});
    for (int step = 0; step < 60 * 120; ++step)
    {
        if (step % 600 == 300)
            ball.placeAt({courtMiddleX, courtMiddleY},
                         {900.f, (random() % 2 ? 1.f : -1.f) * steep(random)});
        ball.move(ball.getVelocity() * dt);
        const hitbox::Box box = boxOf(ball);
        const sf::Vector2f v = ball.getVelocity();
        if (box.left < court.left || hitbox::rightOf(box) > court.right)
            ball.setVelocity({box.left < court.left ? std::abs(v.x) : -std::abs(v.x), v.y});
        ball.bounceOffWalls();
        const hitbox::Box after = boxOf(ball);
        ASSERT_GE(after.top, court.top) << "the ball left through the top at step " << step;
        ASSERT_LE(hitbox::bottomOf(after), court.bottom)
            << "the ball left through the bottom at step " << step;
    }
}

// --- Task 3 --------------------------------------------------------------------------

namespace
{
// The ball, touching the left paddle's front face at `offset` pixels below its middle,
// moving in with `velocity`, is told it hit the paddle. Returns its velocity after.
sf::Vector2f returnOffLeftPaddle(float offset, sf::Vector2f velocity)
{
    Paddle paddle(100.f);
    Ball ball;
    ball.placeAt({hitbox::rightOf(boxOf(paddle)) + ballSize / 2.f, paddle.getPosition().y + offset},
                 velocity);
    ball.collisionResponse(&paddle);
    return ball.getVelocity();
}
} // namespace

TEST(Task3ReturnOffThePaddle, FromTheMiddleItGoesBackFlatAtTheSameSpeed)
{
    for (const sf::Vector2f in : {sf::Vector2f(-ballSpeed, 0.f), sf::Vector2f(-300.f, 350.f)})
    {
        const sf::Vector2f out = returnOffLeftPaddle(0.f, in);
        EXPECT_GT(out.x, 0.f) << "back to the right, away from the left paddle";
        EXPECT_NEAR(degreesFromHorizontal(out), 0.f, 2.f)
            << "the angle is set by where it hit, not by how it came: " << labtesting::text(out);
        EXPECT_NEAR(speedOf(out), speedOf(in), speedOf(in) * 0.01f) << "the speed is kept";
    }
}

TEST(Task3ReturnOffThePaddle, OffTheEndsItLeavesSteeplyButNeverPastTheMaximum)
{
    const float end = paddleHeight / 2.f;
    const sf::Vector2f up = returnOffLeftPaddle(-end, {-ballSpeed, 0.f});
    const sf::Vector2f down = returnOffLeftPaddle(end, {-ballSpeed, 0.f});
    EXPECT_GT(up.x, 0.f);
    EXPECT_GT(down.x, 0.f);
    EXPECT_LE(degreesFromHorizontal(up), -maxBounceDegrees / 2.f) << "off the top end: steeply up";
    EXPECT_GE(degreesFromHorizontal(down), maxBounceDegrees / 2.f)
        << "off the bottom end: steeply down";
    EXPECT_GE(degreesFromHorizontal(up), -maxBounceDegrees - 0.5f);
    EXPECT_LE(degreesFromHorizontal(down), maxBounceDegrees + 0.5f);
}

TEST(Task3ReturnOffThePaddle, TheAngleGrowsTowardsTheEndsAndIsNeverVertical)
{
    // From a corner clipped above the paddle to one clipped below it, and further.
    float previous = -90.f;
    for (float offset = -paddleHeight; offset <= paddleHeight; offset += 2.f)
    {
        const sf::Vector2f out = returnOffLeftPaddle(offset, {-ballSpeed, 120.f});
        const float angle = degreesFromHorizontal(out);
        EXPECT_GT(out.x, 0.f) << "hit " << offset << " px from the middle: not returned";
        EXPECT_LE(std::abs(angle), maxBounceDegrees + 0.5f)
            << "hit " << offset << " px from the middle: " << angle << " degrees";
        EXPECT_GE(angle, previous - 0.01f)
            << "hit " << offset << " px from the middle: lower hits should leave more downwards";
        previous = angle;
    }
}

TEST(Task3ReturnOffThePaddle, WhereItHitCountsHalfTheBall)
{
    // The sheet's rule: where = offset / (paddleHeight / 2 + ballSize / 2), so a ball whose
    // centre is level with the paddle's very end has not quite reached the steepest angle
    // (its half sticks out past the end), and one that only clips the corner has.
    const float reach = paddleHeight / 2.f + ballSize / 2.f;
    for (const float offset : {paddleHeight / 4.f, paddleHeight / 2.f, -paddleHeight / 2.f})
    {
        const sf::Vector2f out = returnOffLeftPaddle(offset, {-ballSpeed, 0.f});
        EXPECT_NEAR(degreesFromHorizontal(out), offset / reach * maxBounceDegrees, 0.2f)
            << "hit " << offset << " px from the middle, with paddleHeight " << paddleHeight
            << " and ballSize " << ballSize;
    }
    EXPECT_NEAR(degreesFromHorizontal(returnOffLeftPaddle(reach, {-ballSpeed, 0.f})),
                maxBounceDegrees, 0.2f)
        << "a ball clipping the bottom corner leaves at the steepest angle";
}

TEST(Task3ReturnOffThePaddle, TheRightPaddleSendsItLeft)
{
    Paddle paddle(1100.f);
    Ball ball;
    ball.placeAt({boxOf(paddle).left - ballSize / 2.f, paddle.getPosition().y + paddleHeight / 4.f},
                 {ballSpeed, 0.f});
    ball.collisionResponse(&paddle);
    EXPECT_LT(ball.getVelocity().x, 0.f);
    EXPECT_GT(ball.getVelocity().y, 0.f) << "hit below the middle: leaves downwards";
    EXPECT_NEAR(speedOf(ball.getVelocity()), ballSpeed, ballSpeed * 0.01f);
}

// --- Task 4 --------------------------------------------------------------------------

TEST(Task4ScoreAndServe, WhollyPastTheLeftLineIsAPointForTheRightAndServedToTheLeft)
{
    PongLevel level(1);
    level.getBall().placeAt({court.left - ballSize / 2.f - 1.f, 300.f}, {-ballSpeed, 0.f});
    level.scoreAndServe();
    EXPECT_EQ(level.getRightScore(), 1);
    EXPECT_EQ(level.getLeftScore(), 0);
    EXPECT_VEC_NEAR(level.getBall().getPosition(), sf::Vector2f(courtMiddleX, courtMiddleY), 0.5f)
        << "served from the middle";
    EXPECT_LT(level.getBall().getVelocity().x, 0.f)
        << "the left player lost the point: served to them";
}

TEST(Task4ScoreAndServe, WhollyPastTheRightLineIsAPointForTheLeftAndServedToTheRight)
{
    PongLevel level(2);
    level.getBall().placeAt({court.right + ballSize / 2.f + 1.f, 300.f}, {ballSpeed, 40.f});
    level.scoreAndServe();
    EXPECT_EQ(level.getLeftScore(), 1);
    EXPECT_EQ(level.getRightScore(), 0);
    EXPECT_VEC_NEAR(level.getBall().getPosition(), sf::Vector2f(courtMiddleX, courtMiddleY), 0.5f);
    EXPECT_GT(level.getBall().getVelocity().x, 0.f)
        << "the right player lost the point: served to them";
}

TEST(Task4ScoreAndServe, TouchingTheLineFromOutsideIsOut)
{
    PongLevel level(3);
    level.getBall().placeAt({court.left - ballSize / 2.f, 300.f}, {-ballSpeed, 0.f});
    level.scoreAndServe();
    EXPECT_EQ(level.getRightScore(), 1) << "a ball touching the left line from outside shares no "
                                           "area with the court: it is out";
    level.getBall().placeAt({court.right + ballSize / 2.f, 300.f}, {ballSpeed, 0.f});
    level.scoreAndServe();
    EXPECT_EQ(level.getLeftScore(), 1);
}

TEST(Task4ScoreAndServe, ABallStillOverTheLineIsInPlay)
{
    PongLevel level(4);
    for (const float x : {court.left, court.left - ballSize / 2.f + 0.5f, court.right,
                          court.right + ballSize / 2.f - 0.5f, courtMiddleX})
    {
        const sf::Vector2f velocity{x < courtMiddleX ? -ballSpeed : ballSpeed, 10.f};
        level.getBall().placeAt({x, 300.f}, velocity);
        level.scoreAndServe();
        EXPECT_EQ(level.getLeftScore() + level.getRightScore(), 0) << "ball centre at x = " << x;
        EXPECT_VEC_NEAR(level.getBall().getPosition(), sf::Vector2f(x, 300.f), 0.f);
        EXPECT_VEC_NEAR(level.getBall().getVelocity(), velocity, 0.f);
    }
}

TEST(Task4ScoreAndServe, OverManyShotsEveryPointCountsOnceAndTheLoserReceives)
{
    // The test moves the ball itself, a step at a time, and calls scoreAndServe after each
    // step (so no paddle, sweep or wall code plays a part). Whenever the ball is served, it
    // plays a flat shot from the middle to the left goal, then to the right one, in turn.
    PongLevel level(5);
    int shots = 0;
    int expectedLeft = 0;
    int expectedRight = 0;
    auto playShot = [&]()
    {
        const bool toTheLeft = shots % 2 == 0;
        level.getBall().placeAt({courtMiddleX, courtMiddleY},
                                {toTheLeft ? -ballSpeed : ballSpeed, 0.f});
        ++shots;
    };
    playShot();
    const int stepsPerShot = static_cast<int>((court.right - court.left) / (ballSpeed * dt)) + 20;
    for (int step = 0; step < 8 * stepsPerShot && shots < 8; ++step)
    {
        const int before = level.getLeftScore() + level.getRightScore();
        const bool toTheLeft = level.getBall().getVelocity().x < 0.f;
        level.getBall().move(level.getBall().getVelocity() * dt);
        level.scoreAndServe();
        const int after = level.getLeftScore() + level.getRightScore();
        if (after != before)
        {
            ASSERT_EQ(after, before + 1) << "one point at a time";
            (toTheLeft ? expectedRight : expectedLeft) += 1;
            EXPECT_EQ(level.getLeftScore(), expectedLeft);
            EXPECT_EQ(level.getRightScore(), expectedRight);
            EXPECT_EQ(level.getBall().getVelocity().x < 0.f, toTheLeft)
                << "the serve goes towards the player who lost the point";
            playShot();
        }
    }
    EXPECT_EQ(shots, 8) << "every shot past the goal line is a point";
    EXPECT_EQ(expectedLeft + expectedRight, 7);
}

// --- Task 5 --------------------------------------------------------------------------

TEST(Task5SweepTheBallAgainstThePaddles, AFastBallNeverPassesAStillPaddle)
{
    // At the fastest speeds the ball crosses the whole court in a step: returned by the left
    // paddle, it meets the right one within the same step. It never gets past either face.
    for (const float speed : {ballSpeed, 3000.f, 30000.f, 300000.f, 3e6f})
    {
        Paddles paddles;
        RecordingBall ball;
        const float leftFace = hitbox::rightOf(boxOf(paddles.left));
        const float rightFace = boxOf(paddles.right).left;
        ball.placeAt({leftFace + 400.f, paddles.left.getPosition().y + 20.f}, {-speed, 0.f});
        for (int step = 0; step < 240 && ball.hits.empty(); ++step)
        {
            moveBall(ball, paddles.left, paddles.right, dt);
            ASSERT_GE(boxOf(ball).left, leftFace - 0.01f)
                << "at " << speed << " px/s the ball went into or through the left paddle";
            ASSERT_LE(hitbox::rightOf(boxOf(ball)), rightFace + 0.01f)
                << "at " << speed << " px/s the ball went into or through the right paddle";
        }
        ASSERT_FALSE(ball.hits.empty()) << "at " << speed << " px/s: the paddle was never hit";
        EXPECT_EQ(ball.hits[0], &paddles.left) << "at " << speed << " px/s";
    }
}

TEST(Task5SweepTheBallAgainstThePaddles, ABallNeverPassesAPaddleMovingIntoItsPath)
{
    // In one step the ball crosses the paddle's line (100 px) while the paddle moves down
    // into its path: at neither the start nor the end of the step do they overlap.
    Paddles paddles;
    RecordingBall ball;
    const float face = boxOf(paddles.right).left;
    const float ballY = 300.f;
    paddles.right.setPosition(
        {paddles.right.getPosition().x, ballY - paddleHeight / 2.f - ballSize / 2.f - 10.f});
    paddles.right.setPlannedMove({0.f, 40.f});
    ball.placeAt({face - ballSize / 2.f - 50.f, ballY}, {100.f / dt, 0.f});
    moveBall(ball, paddles.left, paddles.right, dt);
    ASSERT_EQ(ball.hits.size(), 1u) << "the moving paddle was in the ball's way";
    EXPECT_EQ(ball.hits[0], &paddles.right);
    EXPECT_LE(hitbox::rightOf(boxOf(ball)), face + 0.01f) << "the ball went through the paddle";
    EXPECT_EQ(paddles.right.getPlannedMove(), sf::Vector2f(0.f, 40.f))
        << "paddles move in finishMove";
}

TEST(Task5SweepTheBallAgainstThePaddles, ABallThatMissesFliesOnTheWholeStep)
{
    // Passing just above the paddle (touching its top end is not hitting it), and far from both.
    Paddles paddles;
    RecordingBall ball;
    const sf::Vector2f start{hitbox::rightOf(boxOf(paddles.left)) + 30.f,
                             boxOf(paddles.left).top - ballSize / 2.f};
    ball.placeAt(start, {-60.f / dt, 0.f});
    moveBall(ball, paddles.left, paddles.right, dt);
    EXPECT_TRUE(ball.hits.empty()) << "sliding along the paddle's top end is not a hit";
    EXPECT_VEC_NEAR(ball.getPosition(), start + sf::Vector2f(-60.f, 0.f), 1e-3f);

    ball.placeAt({courtMiddleX, courtMiddleY}, {300.f, -200.f});
    moveBall(ball, paddles.left, paddles.right, dt);
    EXPECT_TRUE(ball.hits.empty());
    EXPECT_VEC_NEAR(ball.getPosition(),
                    sf::Vector2f(courtMiddleX, courtMiddleY) + sf::Vector2f(300.f, -200.f) * dt,
                    1e-3f);
}

TEST(Task5SweepTheBallAgainstThePaddles, AfterAHitTheBallUsesTheRestOfTheStep)
{
    // 60 px a step, 20 px in front of the left paddle: a third of the step to reach it, then
    // (turned round by the response) the other 40 px away from it, all in one step.
    Paddles paddles;
    RecordingBall ball;
    const float face = hitbox::rightOf(boxOf(paddles.left));
    ball.placeAt({face + 20.f + ballSize / 2.f, paddles.left.getPosition().y}, {-60.f / dt, 0.f});
    moveBall(ball, paddles.left, paddles.right, dt);
    ASSERT_EQ(ball.hits.size(), 1u) << "the ball met the left paddle in this step";
    EXPECT_NEAR(boxOf(ball).left, face + 40.f, 0.01f)
        << "first up to the paddle (20 px), then the rest of the step (40 px) back: "
           "move by ballMove * hit.time before the response, then on for what is left";
}

TEST(Task5SweepTheBallAgainstThePaddles, TwoHitsInOneStepMeetThePaddleWhereItIsThen)
{
    // A ball so fast it crosses the court twice a step: a quarter of the step to the left
    // paddle, half a step across to the right one, which moves down 200 px during the step.
    // At three quarters of the step it has moved 150 px and is in the ball's way; where it
    // stood at the start, or only moved by its move over the rest of the step, it would not be.
    Paddles paddles;
    RecordingBall ball;
    const float leftFace = hitbox::rightOf(boxOf(paddles.left));
    const float rightFace = boxOf(paddles.right).left;
    const float across = rightFace - leftFace - ballSize; // between the two faces
    const float ballY = hitbox::bottomOf(boxOf(paddles.right)) + 125.f + ballSize / 2.f;
    paddles.left.setPosition({paddles.left.getPosition().x, ballY});
    paddles.right.setPlannedMove({0.f, 200.f});
    ball.placeAt({leftFace + across / 2.f + ballSize / 2.f, ballY}, {-2.f * across / dt, 0.f});
    moveBall(ball, paddles.left, paddles.right, dt);
    ASSERT_EQ(ball.hits.size(), 2u) << "the left paddle, then the right one, in one step";
    EXPECT_EQ(ball.hits[0], &paddles.left);
    EXPECT_EQ(ball.hits[1], &paddles.right)
        << "the right paddle, 3/4 through its move (150 px down), was in the ball's way";
    EXPECT_NEAR(hitbox::rightOf(boxOf(ball)), rightFace - across / 2.f, 0.05f)
        << "after the second hit, the last quarter of the step back to the left";
}

TEST(Task5SweepTheBallAgainstThePaddles, ABallStartingInsideAPaddleIsPushedOut)
{
    // A paddle moved into the ball between steps: the ball starts 3 px inside its face.
    Paddles paddles;
    RecordingBall ball;
    const float face = boxOf(paddles.right).left;
    ball.placeAt({face + 3.f - ballSize / 2.f, paddles.right.getPosition().y}, {30.f / dt, 0.f});
    moveBall(ball, paddles.left, paddles.right, dt);
    ASSERT_FALSE(ball.hits.empty()) << "a ball inside the paddle touches it";
    EXPECT_EQ(ball.hits[0], &paddles.right);
    EXPECT_LE(hitbox::rightOf(boxOf(ball)), face + 0.01f)
        << "pushed out along the hit's normal (by its depth) when the hit started inside";
}

namespace
{
// A ball whose response does not turn it round (as one squeezed between a paddle's end and a
// wall can be): it keeps meeting the same face, at time 0, for the rest of the step.
class BallThatKeepsComing : public Ball
{
public:
    void collisionResponse(hitbox::GameObject*) override { ++hits; }
    int hits = 0;
};
} // namespace

TEST(Task5SweepTheBallAgainstThePaddles, ABallThatKeepsComingIsSweptOnlyAFewTimesAStep)
{
    // The sheet: sweep again with what is left, at most a few times. Without the cap this
    // step never ends (each hit at time 0 leaves all the time there was).
    Paddles paddles;
    BallThatKeepsComing ball;
    const float face = boxOf(paddles.right).left;
    ball.placeAt({face - 20.f - ballSize / 2.f, paddles.right.getPosition().y}, {60.f / dt, 0.f});
    moveBall(ball, paddles.left, paddles.right, dt);
    EXPECT_GE(ball.hits, 1) << "the ball met the right paddle";
    EXPECT_LE(ball.hits, 16) << "swept again and again in one step";
    EXPECT_NEAR(hitbox::rightOf(boxOf(ball)), face, 0.01f) << "stopped touching the face";
}

TEST(Task5SweepTheBallAgainstThePaddles, InAMatchOfVeryFastBallsNoneCrossesAPaddle)
{
    // The test plays the match itself with moveBall alone (so task 1's paddle code and task
    // 4's scoring play no part): every half second it puts the paddles anywhere in the court
    // and shoots a very fast ball from the middle at one of them; each step each paddle
    // plans a random move up or down. After each step, a ball whose move met a paddle's
    // front face (the framework's sweep says so) must still be in front of it.
    Paddles paddles;
    RecordingBall ball;
    std::mt19937 random(21);
    std::uniform_real_distribution<float> paddleY(court.top + paddleHeight / 2.f,
                                                  court.bottom - paddleHeight / 2.f);
    std::uniform_real_distribution<float> paddleMove(-paddleSpeed * dt, paddleSpeed * dt);
    int faceHits = 0;
    for (int step = 0; step < 30 * 120; ++step)
    {
        if (step % 60 == 0)
        {
            for (Paddle* paddle : {&paddles.left, &paddles.right})
                paddle->setPosition({paddle->getPosition().x, paddleY(random)});
            const Paddle& target = random() % 2 ? paddles.left : paddles.right;
            const sf::Vector2f from{courtMiddleX, courtMiddleY};
            const sf::Vector2f aim = target.getPosition() - from;
            const float speed = std::uniform_real_distribution<float>(2000.f, 40000.f)(random);
            ball.placeAt(from, aim / speedOf(aim) * speed);
        }
        const sf::Vector2f leftMove{0.f, paddleMove(random)};
        const sf::Vector2f rightMove{0.f, paddleMove(random)};
        paddles.left.setPlannedMove(leftMove);
        paddles.right.setPlannedMove(rightMove);
        const hitbox::Box ballBefore = boxOf(ball);
        const sf::Vector2f move = ball.getVelocity() * dt;
        const hitbox::Box leftBefore = boxOf(paddles.left);
        const hitbox::Box rightBefore = boxOf(paddles.right);
        moveBall(ball, paddles.left, paddles.right, dt);
        paddles.left.finishMove();
        paddles.right.finishMove();
        const hitbox::Box ballAfter = boxOf(ball);
        if (shouldHitFace(ballBefore, move, leftBefore, leftMove, 1.f))
        {
            ++faceHits;
            ASSERT_GE(ballAfter.left, hitbox::rightOf(leftBefore) - 0.01f)
                << "step " << step << ": the ball crossed the left paddle at " << speedOf(move / dt)
                << " px/s";
        }
        if (shouldHitFace(ballBefore, move, rightBefore, rightMove, -1.f))
        {
            ++faceHits;
            ASSERT_LE(hitbox::rightOf(ballAfter), rightBefore.left + 0.01f)
                << "step " << step << ": the ball crossed the right paddle at "
                << speedOf(move / dt) << " px/s";
        }
    }
    EXPECT_GT(faceHits, 20) << "the test shot at the paddles; most shots should meet one";
}

// --- Task 6 --------------------------------------------------------------------------

namespace
{
// Plays the computer's paddle against a ball flying straight (no walls in the way) until
// the ball reaches the paddle's face. The test moves the paddle itself by the direction the
// computer chose. Returns true when the paddle was there to meet it.
bool computerMeets(Paddle& paddle, Ball& ball, float& fastest)
{
    const float face = boxOf(paddle).left;
    for (int step = 0; step < 10 * 120; ++step)
    {
        const float direction = computerDirection(ball, paddle, dt);
        fastest = std::max(fastest, std::abs(direction));
        paddle.move({0.f, std::clamp(direction, -1.f, 1.f) * paddleSpeed * dt});
        ball.move(ball.getVelocity() * dt);
        if (hitbox::rightOf(boxOf(ball)) >= face)
        {
            const hitbox::Box at = boxOf(paddle);
            const hitbox::Box b = boxOf(ball);
            return b.top < hitbox::bottomOf(at) && at.top < hitbox::bottomOf(b);
        }
    }
    return false;
}
} // namespace

TEST(Task6ComputerOpponent, ItReturnsAnEasyBall)
{
    // A flat ball at serve speed, aimed to pass just beside the paddle where it stands.
    for (const float side : {-1.f, 1.f})
    {
        Paddle paddle(court.right - paddleInset - paddleWidth / 2.f);
        Ball ball;
        const float beside = paddleHeight / 2.f + ballSize / 2.f + 40.f;
        // The test's own speed: time for the paddle to travel three times the 40 px it needs.
        const float easySpeed = 600.f / (3.f * 40.f / (computerTopSpeed * paddleSpeed));
        ball.placeAt({boxOf(paddle).left - 600.f, paddle.getPosition().y + side * beside},
                     {easySpeed, 0.f});
        float fastest = 0.f;
        EXPECT_TRUE(computerMeets(paddle, ball, fastest))
            << "a flat ball " << beside << " px " << (side < 0 ? "above" : "below")
            << " its paddle, 600 px away: the computer should get there";
    }
}

TEST(Task6ComputerOpponent, ItIsNeverFasterThanItsTopSpeed)
{
    std::mt19937 random(3);
    std::uniform_real_distribution<float> x(court.left, court.right);
    std::uniform_real_distribution<float> y(court.top, court.bottom);
    std::uniform_real_distribution<float> speed(-3000.f, 3000.f);
    for (int trial = 0; trial < 2000; ++trial)
    {
        Paddle paddle(trial % 2 ? court.right - paddleInset : court.left + paddleInset);
        paddle.setPosition({paddle.getPosition().x, y(random)});
        Ball ball;
        ball.placeAt({x(random), y(random)}, {speed(random), speed(random)});
        const float direction = computerDirection(ball, paddle, dt);
        ASSERT_LE(std::abs(direction), computerTopSpeed + 1e-4f)
            << "the computer's paddle may move at most computerTopSpeed (" << computerTopSpeed
            << ") of a player's; it chose " << direction;
    }
}

TEST(Task6ComputerOpponent, AShotPlacedOutOfItsReachBeatsIt)
{
    // Its paddle touching the bottom wall, a flat ball along the top wall 300 px away. The
    // test picks the ball's speed itself, so the paddle at its top speed covers only half
    // the gap before the ball arrives, whatever the numbers in Court.h are.
    Paddle paddle(court.right - paddleInset - paddleWidth / 2.f);
    paddle.setPosition({paddle.getPosition().x, court.bottom - paddleHeight / 2.f});
    const float ballY = court.top + ballSize / 2.f;
    const float gap = paddle.getPosition().y - ballY - paddleHeight / 2.f - ballSize / 2.f;
    ASSERT_GT(gap, 0.f) << "Court.h: the court should be taller than a paddle and a ball";
    const float arrives = (gap / 2.f) / (computerTopSpeed * paddleSpeed);
    Ball ball;
    ball.placeAt({boxOf(paddle).left - 300.f - ballSize / 2.f, ballY}, {300.f / arrives, 0.f});
    float fastest = 0.f;
    EXPECT_FALSE(computerMeets(paddle, ball, fastest))
        << "the computer reached a ball it should not be fast enough to reach";
    EXPECT_GT(fastest, 0.f) << "it did not even try";
}

TEST(Task6ComputerOpponent, CloseToItsTargetItStopsThereInsteadOfShaking)
{
    // The ball comes straight at it, 1 px below the paddle's middle: one step at top speed
    // would overshoot by more than a pixel, so it moves just the pixel (dividing the distance
    // by paddleSpeed * dt turns it into a direction).
    Paddle paddle(court.right - paddleInset - paddleWidth / 2.f);
    const float startY = paddle.getPosition().y;
    Ball ball;
    ball.placeAt({paddle.getPosition().x - 400.f, startY + 1.f}, {ballSpeed, 0.f});
    const float direction = computerDirection(ball, paddle, dt);
    const float moved = std::clamp(direction, -1.f, 1.f) * paddleSpeed * dt;
    EXPECT_GE(moved, 0.f) << "the ball is below: it should move down, or not at all";
    EXPECT_LE(moved, 1.f + 0.01f) << "it moved " << moved << " px towards a target 1 px away";
}

namespace
{
// The computer's paddle on one side: -1 the left one, +1 the right one. A ball moving with
// x velocity of that sign is coming towards it.
Paddle computerPaddle(float side, float y)
{
    Paddle paddle(side < 0.f ? court.left + paddleInset + paddleWidth / 2.f
                             : court.right - paddleInset - paddleWidth / 2.f);
    paddle.setPosition({paddle.getPosition().x, y});
    return paddle;
}

const float bothSides[] = {-1.f, 1.f};
} // namespace

TEST(Task6ComputerOpponent, WhenTheBallGoesAwayItGoesBackToTheMiddle)
{
    for (const float side : bothSides)
        for (const float below : {-100.f, 100.f})
            for (const float speed : {ballSpeed, 0.001f})
            {
                const Paddle paddle = computerPaddle(side, courtMiddleY + below);
                Ball ball;
                // Going away, level with the paddle's height (so heading for the ball would
                // mean standing still).
                ball.placeAt({courtMiddleX, paddle.getPosition().y}, {-side * speed, 0.f});
                EXPECT_LT(computerDirection(ball, paddle, dt) * below, 0.f)
                    << (side < 0 ? "left" : "right") << " paddle " << std::abs(below) << " px "
                    << (below < 0 ? "above" : "below") << " the middle, the ball going away at "
                    << speed << " px/s: it should head back to the middle";
            }
}

TEST(Task6ComputerOpponent, ASlowBallComingTowardsItIsFollowed)
{
    // A thousandth of a pixel a second towards the paddle is still coming: head for its height.
    for (const float side : bothSides)
    {
        const Paddle paddle = computerPaddle(side, courtMiddleY);
        Ball ball;
        ball.placeAt({courtMiddleX, courtMiddleY + 100.f}, {side * 0.001f, 0.f});
        EXPECT_GT(computerDirection(ball, paddle, dt), 0.f)
            << (side < 0 ? "left" : "right") << " paddle: the ball is below and coming";
    }
}

TEST(Task6ComputerOpponent, ABallLevelWithItOrNotMovingSidewaysIsNotComing)
{
    // The sheet's rule: such a ball is not coming, so the paddle goes back to the middle
    // (here up), not after the ball (here down).
    for (const float side : bothSides)
    {
        const Paddle paddle = computerPaddle(side, courtMiddleY + 100.f);
        const char* which = side < 0 ? "left paddle: " : "right paddle: ";
        Ball straightDown;
        straightDown.placeAt({courtMiddleX, courtMiddleY + 150.f}, {0.f, 300.f});
        EXPECT_LT(computerDirection(straightDown, paddle, dt), 0.f) << which << "no sideways speed";
        for (const float way : {-1.f, 1.f})
        {
            Ball level;
            level.placeAt({paddle.getPosition().x, courtMiddleY + 150.f}, {way * ballSpeed, 0.f});
            EXPECT_LT(computerDirection(level, paddle, dt), 0.f)
                << which << "level with the paddle, moving " << (way < 0 ? "left" : "right");
        }
    }
}

TEST(Task6ComputerOpponent, WhenNoTimePassesItStandsStill)
{
    // dt == 0: nothing to divide by, so the sheet says 0 - also when the ball is level.
    Paddle paddle(court.right - paddleInset - paddleWidth / 2.f);
    for (const float below : {100.f, 0.f})
    {
        Ball ball;
        ball.placeAt({paddle.getPosition().x - 400.f, paddle.getPosition().y + below},
                     {ballSpeed, 0.f});
        EXPECT_EQ(computerDirection(ball, paddle, 0.f), 0.f) << "ball " << below << " px below";
    }
}
