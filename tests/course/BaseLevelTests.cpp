// BaseLevel: the old level base. Without a window its drawing calls do nothing.
#include "Framework/BaseLevel.h"

#include <gtest/gtest.h>

namespace
{

class EmptyLevel : public BaseLevel
{
public:
    void handleInput(float) override {}
    void update(float) override {}
    void render() override
    {
        beginDraw();
        endDraw();
    }
    bool startsWithNoWindowOrInput() const { return window == nullptr && input == nullptr; }
};

} // namespace

TEST(BaseLevel, NewLevelHasNoWindowOrInputUntilItsConstructorSetsThem)
{
    const EmptyLevel level;
    EXPECT_TRUE(level.startsWithNoWindowOrInput());
}

TEST(BaseLevel, RenderWithoutAWindowDoesNotCrash)
{
    EmptyLevel level;
    level.render();
    SUCCEED();
}

TEST(BaseLevel, ClearsToTheOldFrameworksLightBlue)
{
    EXPECT_EQ(BaseLevel::backgroundColor, sf::Color(100, 149, 237));
}
