#include "hitbox/app/Replay.h"

#include "hitbox/app/Csv.h"
#include "hitbox/app/Keys.h"
#include "hitbox/app/Options.h"

#include <algorithm>
#include <charconv>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

namespace hitbox
{
namespace
{

bool sameBits(float a, float b)
{
    return std::memcmp(&a, &b, sizeof(float)) == 0;
}

bool sameButton(const ButtonSnapshot& a, const ButtonSnapshot& b)
{
    return a.down == b.down && a.pressed == b.pressed && a.released == b.released;
}

ButtonSnapshot leftOf(const Input& input)
{
    return {input.isLeftMouseDown(), input.isLeftMousePressed(), input.isLeftMouseReleased()};
}

ButtonSnapshot rightOf(const Input& input)
{
    return {input.isRightMouseDown(), input.isRightMousePressed(), input.isRightMouseReleased()};
}

bool contains(const std::vector<int>& keys, int key)
{
    return std::binary_search(keys.begin(), keys.end(), key);
}

// Drives one key or button through Input's own setters to the state `wanted`: held before
// this step (down, then update() to forget the press), let go, pressed, let go again. Every
// combination Input can reach comes out of these four phases in this order.
void replayPhases(Input& input, int phase, bool down, bool pressed, bool released,
                  void (*set)(Input&, int, bool), int which)
{
    if (phase == 0 && ((down && !pressed) || released))
        set(input, which, true);
    if (phase == 1 && released)
        set(input, which, false);
    if (phase == 2 && pressed)
        set(input, which, true);
    if (phase == 3 && pressed && !down)
        set(input, which, false);
}

void setKey(Input& input, int key, bool down)
{
    if (down)
        input.setKeyDown(key);
    else
        input.setKeyUp(key);
}

void setButton(Input& input, int right, bool down)
{
    if (right != 0)
        input.setMouseRDown(down);
    else
        input.setMouseLDown(down);
}

std::string keyList(const std::vector<int>& keys)
{
    std::string text;
    for (int key : keys)
        text += (text.empty() ? "" : " ") + std::to_string(key);
    return text;
}

std::string flags(const ButtonSnapshot& button)
{
    return std::string(button.down ? "d" : "") + (button.pressed ? "p" : "") +
           (button.released ? "r" : "");
}

// Everything below reads one field; a bad one throws with the message for ReplayRead.
long long wholeNumber(const std::string& text, long long lowest, long long highest,
                      const std::string& what)
{
    long long value = 0;
    const char* end = text.data() + text.size();
    const std::from_chars_result result = std::from_chars(text.data(), end, value);
    if (text.empty() || result.ec != std::errc() || result.ptr != end || value < lowest ||
        value > highest)
        throw std::invalid_argument(what + " needs a whole number from " + std::to_string(lowest) +
                                    " to " + std::to_string(highest) + ", not '" + printable(text) +
                                    "'");
    return value;
}

std::vector<int> readKeys(const std::string& text)
{
    std::vector<int> keys;
    std::istringstream words(text);
    std::string word;
    while (words >> word)
        keys.push_back(static_cast<int>(wholeNumber(word, 0, keyCount - 1, "a key code")));
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    return keys;
}

ButtonSnapshot readFlags(const std::string& text)
{
    const ButtonSnapshot button{text.find('d') != std::string::npos,
                                text.find('p') != std::string::npos,
                                text.find('r') != std::string::npos};
    if (flags(button) != text)
        throw std::invalid_argument("a mouse button needs its flags d, p, r in that order, not '" +
                                    printable(text) + "'");
    return button;
}

float readFloat(const std::string& text, const std::string& what)
{
    float value = 0.f;
    if (!readExact(text, value))
        throw std::invalid_argument(what + " needs a number, not '" + printable(text) + "'");
    return value;
}

void expectFields(const std::vector<std::string>& row, std::size_t count)
{
    if (row.size() != count)
        throw std::invalid_argument("a '" + printable(row[0]) + "' row has " +
                                    std::to_string(count) + " fields, this one " +
                                    std::to_string(row.size()));
}

std::pair<long long, InputSnapshot> readInputRow(const std::vector<std::string>& row)
{
    expectFields(row, 10);
    InputSnapshot input;
    const long long step = wholeNumber(row[1], 0, maxSeconds * 1000, "the step");
    input.keysDown = readKeys(row[2]);
    input.keysPressed = readKeys(row[3]);
    input.keysReleased = readKeys(row[4]);
    input.mouseX = readFloat(row[5], "the mouse's x");
    input.mouseY = readFloat(row[6], "the mouse's y");
    input.left = readFlags(row[7]);
    input.right = readFlags(row[8]);
    input.wheel = readFloat(row[9], "the wheel");
    return {step, input};
}

// Reads every row; throws std::invalid_argument("row N: ...") at the first bad one.
Recording readRows(std::istream& in)
{
    Recording recording;
    std::vector<std::string> row;
    std::vector<std::string> seen;
    long long rowNumber = 0;
    std::string problem;
    while (readCsvRow(in, row, problem))
    {
        ++rowNumber;
        const std::string at = "row " + std::to_string(rowNumber) + ": ";
        try
        {
            if (rowNumber == 1)
            {
                if (row[0] != "hitbox-replay")
                    throw std::invalid_argument("not a Hitbox replay (its first row should be "
                                                "'hitbox-replay," +
                                                std::to_string(replayFormatVersion) + "')");
                expectFields(row, 2);
                const long long version = wholeNumber(row[1], 1, 1000000, "the version");
                if (version != replayFormatVersion)
                    throw std::invalid_argument("a replay of format " + std::to_string(version) +
                                                "; this Hitbox reads format " +
                                                std::to_string(replayFormatVersion));
                continue;
            }
            const std::string& kind = row[0];
            const bool once =
                kind == "program" || kind == "seed" || kind == "headless" || kind == "steps";
            if (once && std::find(seen.begin(), seen.end(), kind) != seen.end())
                throw std::invalid_argument("'" + kind + "' is given twice");
            seen.push_back(kind);
            expectFields(row, kind == "option" ? 3 : kind == "input" ? 10 : 2);
            if (kind == "program")
                recording.program = row[1];
            else if (kind == "seed")
                recording.seed = static_cast<unsigned>(wholeNumber(row[1], 0, 4294967295, kind));
            else if (kind == "headless")
            {
                if (row[1] != "yes" && row[1] != "no")
                    throw std::invalid_argument("headless needs yes or no, not '" +
                                                printable(row[1]) + "'");
                recording.headless = row[1] == "yes";
            }
            else if (kind == "option")
                recording.options[row[1]] = row[2];
            else if (kind == "steps")
                recording.steps = wholeNumber(row[1], 0, maxSeconds * 1000, kind);
            else if (kind == "input")
            {
                auto change = readInputRow(row);
                if (!recording.changes.empty() && change.first <= recording.changes.back().first)
                    throw std::invalid_argument("input rows must come in order of their steps");
                recording.changes.push_back(change);
            }
            else
                throw std::invalid_argument("unknown row '" + printable(kind) + "'");
        }
        catch (const std::invalid_argument& error)
        {
            throw std::invalid_argument(at + error.what());
        }
    }
    if (!problem.empty())
        throw std::invalid_argument("row " + std::to_string(rowNumber + 1) + ": " + problem);
    if (rowNumber == 0)
        throw std::invalid_argument("the file is empty");
    for (const char* needed : {"program", "seed", "headless", "steps"})
        if (std::find(seen.begin(), seen.end(), needed) == seen.end())
            throw std::invalid_argument("it has no '" + std::string(needed) + "' row");
    if (!recording.changes.empty() && recording.changes.back().first >= recording.steps)
        throw std::invalid_argument("an input row is for a step after the last recorded one");
    return recording;
}

} // namespace

bool sameInput(const InputSnapshot& a, const InputSnapshot& b)
{
    return a.keysDown == b.keysDown && a.keysPressed == b.keysPressed &&
           a.keysReleased == b.keysReleased && sameBits(a.mouseX, b.mouseX) &&
           sameBits(a.mouseY, b.mouseY) && sameButton(a.left, b.left) &&
           sameButton(a.right, b.right) && sameBits(a.wheel, b.wheel);
}

InputSnapshot captureInput(const Input& input)
{
    InputSnapshot snapshot;
    for (int key = 0; key < keyCount; ++key)
    {
        if (input.isKeyDown(key))
            snapshot.keysDown.push_back(key);
        if (input.isPressed(key))
            snapshot.keysPressed.push_back(key);
        if (input.isReleased(key))
            snapshot.keysReleased.push_back(key);
    }
    const sf::Vector2f mouse = input.getMousePosition();
    snapshot.mouseX = mouse.x;
    snapshot.mouseY = mouse.y;
    snapshot.left = leftOf(input);
    snapshot.right = rightOf(input);
    snapshot.wheel = input.getMouseWheel();
    return snapshot;
}

Input restoreInput(const InputSnapshot& snapshot)
{
    // Only the keys the snapshot names: a key in none of its lists is up, as in a new Input
    // (and trying all hundred keys made re-simulating a rewound level slow, RewindReplay.h).
    std::vector<int> named = snapshot.keysDown;
    named.insert(named.end(), snapshot.keysPressed.begin(), snapshot.keysPressed.end());
    named.insert(named.end(), snapshot.keysReleased.begin(), snapshot.keysReleased.end());
    std::sort(named.begin(), named.end());
    named.erase(std::unique(named.begin(), named.end()), named.end());
    Input input;
    for (int phase = 0; phase < 4; ++phase)
    {
        for (int key : named)
            replayPhases(input, phase, contains(snapshot.keysDown, key),
                         contains(snapshot.keysPressed, key), contains(snapshot.keysReleased, key),
                         setKey, key);
        for (int right = 0; right < 2; ++right)
        {
            const ButtonSnapshot& button = right != 0 ? snapshot.right : snapshot.left;
            replayPhases(input, phase, button.down, button.pressed, button.released, setButton,
                         right);
        }
        if (phase == 0)
            input.update(); // what was held before this step is no longer "pressed"
    }
    input.setMousePosition(sf::Vector2f(snapshot.mouseX, snapshot.mouseY));
    input.addMouseWheel(snapshot.wheel);
    return input;
}

void Recording::addStep(const InputSnapshot& input)
{
    if (changes.empty() ? !sameInput(input, InputSnapshot{})
                        : !sameInput(input, changes.back().second))
        changes.emplace_back(steps, input);
    ++steps;
}

InputSnapshot Recording::inputAt(long long step) const
{
    const auto after = std::upper_bound(changes.begin(), changes.end(), step,
                                        [](long long wanted, const auto& change)
                                        { return wanted < change.first; });
    return after == changes.begin() ? InputSnapshot{} : std::prev(after)->second;
}

std::string replayText(const Recording& recording)
{
    std::ostringstream text;
    CsvWriter csv(text);
    csv.row({"hitbox-replay", std::to_string(replayFormatVersion)});
    csv.row({"program", recording.program});
    csv.row({"seed", std::to_string(recording.seed)});
    csv.row({"headless", recording.headless ? "yes" : "no"});
    for (const auto& [name, value] : recording.options)
        csv.row({"option", name, value});
    csv.row({"steps", std::to_string(recording.steps)});
    for (const auto& [step, input] : recording.changes)
        csv.row({"input", std::to_string(step), keyList(input.keysDown), keyList(input.keysPressed),
                 keyList(input.keysReleased), exactText(input.mouseX), exactText(input.mouseY),
                 flags(input.left), flags(input.right), exactText(input.wheel)});
    return text.str();
}

ReplayRead readReplayText(const std::string& text)
{
    std::istringstream in(text);
    try
    {
        return {true, readRows(in), ""};
    }
    catch (const std::invalid_argument& error)
    {
        return {false, {}, error.what()};
    }
}

ReplayRead readReplayFile(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return {false, {}, "cannot open '" + printable(path, 200) + "'"};
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ReplayRead read = readReplayText(text);
    if (!read)
        read.problem = "'" + printable(path, 200) + "' " + read.problem;
    return read;
}

} // namespace hitbox
