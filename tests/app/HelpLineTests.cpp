// The help line along the bottom of every window (app/private/HelpLine.h): the shared keys,
// the level's, the frame rate; with F1 on, the debug legend first.
#include "hitbox/app/Keys.h"
#include "hitbox/app/Level.h"
#include "hitbox/app/private/HelpLine.h"
#include "hitbox/debug/DebugRenderer.h"

#include <gtest/gtest.h>

#include <string>

namespace
{

class KeysLevel : public hitbox::Level
{
public:
    void update(float) override {}
    void render(sf::RenderTarget&) const override {}
    std::string getHelpText() const override { return keys; }
    std::string keys;
};

} // namespace

// The level's text (its score, its keys) before the shared keys: a narrow window cuts the end
// of the line, and the shared keys are the same in every program.
TEST(HelpLine, TheLevelsTextThenTheSharedKeysThenTheFrameRate)
{
    KeysLevel level;
    EXPECT_EQ(hitbox::helpLine(level, false, 0), hitbox::sharedKeysHelp());
    level.keys = "W/S move";
    EXPECT_EQ(hitbox::helpLine(level, false, 59),
              "W/S move   |   " + hitbox::sharedKeysHelp() + "   |   59 fps");
}

TEST(HelpLine, TheDebugLegendComesFirstWhereItIsNeverCutOff)
{
    KeysLevel level;
    const std::string line = hitbox::helpLine(level, true, 0);
    EXPECT_EQ(line.rfind(hitbox::DebugRenderer::legend, 0), 0u) << line;
    EXPECT_NE(line.find(hitbox::sharedKeysHelp()), std::string::npos) << line;
}

// The help line names each shared key from the key in its row (Keys.h), so changing a key
// changes its name on screen too.
TEST(HelpLine, SharedKeysAreNamedFromTheirKeys)
{
    EXPECT_EQ(hitbox::sharedKeysHelp(),
              "F1 debug boxes   P pause   N step   F12 screenshot   Esc quit");
    EXPECT_EQ(hitbox::keyName(sf::Keyboard::Key::A), "A");
    EXPECT_EQ(hitbox::keyName(sf::Keyboard::Key::Z), "Z");
    EXPECT_EQ(hitbox::keyName(sf::Keyboard::Key::F15), "F15");
    EXPECT_EQ(hitbox::keyName(sf::Keyboard::Key::Space),
              "key " + std::to_string(static_cast<int>(sf::Keyboard::Key::Space)));
}
