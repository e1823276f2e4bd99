// Fuzz target: a World changed from inside its own collision responses (issue 25, item 1).
// The input places up to 16 squares and gives each an action it takes whenever it is told of
// a collision: remove, kill, revive, re-add, destroy (itself or another), add a new object,
// stop being a collider, move. Then a few passes run, with more actions between them.
// Any sanitizer report is a bug, and so is a broken rule of World.h / ContactEvent.h:
//   - a pass never reports the same pair twice;
//   - an object's events make sense: Stay and Exit only while it is in a contact, Enter and
//     Exit balance, and after clear() every surviving object is in no contact.
// A failing input goes into corpus/world/ as a regression test.
#include "hitbox/objects/GameObject.h"
#include "hitbox/objects/World.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <vector>

namespace
{

// Reads the input a byte at a time; past the end every byte is 0.
class Bytes
{
public:
    Bytes(const std::uint8_t* data, std::size_t size) : data(data), size(size) {}
    std::uint8_t next() { return at < size ? data[at++] : 0; }
    bool empty() const { return at >= size; }

private:
    const std::uint8_t* data;
    std::size_t size;
    std::size_t at = 0;
};

const std::size_t maxObjects = 48;

struct Scene;

class FuzzObject : public hitbox::GameObject
{
public:
    FuzzObject(Scene& scene, std::uint8_t place, std::uint8_t action) : scene(scene), action(action)
    {
        setSize({8.f + static_cast<float>(place % 4) * 8.f, 16.f});
        setPosition(
            {static_cast<float>(place / 4 % 8) * 10.f, static_cast<float>(place / 32) * 6.f});
    }
    void collisionResponse(hitbox::GameObject* other) override;
    void onCollisionEnter(const hitbox::CollisionEvent& event) override
    {
        if (event.phase != hitbox::ContactPhase::Enter)
            std::abort();
        ++inContacts;
    }
    void onCollisionStay(const hitbox::CollisionEvent& event) override
    {
        if (event.phase != hitbox::ContactPhase::Stay || inContacts <= 0)
            std::abort();
    }
    void onCollisionExit(const hitbox::CollisionEvent& event) override
    {
        if (event.phase != hitbox::ContactPhase::Exit || inContacts <= 0)
            std::abort();
        --inContacts;
    }
    int inContacts = 0;

private:
    Scene& scene;
    std::uint8_t action;
};

struct Scene
{
    hitbox::World world;
    std::vector<std::unique_ptr<FuzzObject>> objects;
    Bytes* bytes = nullptr;

    FuzzObject* pick(std::uint8_t which)
    {
        return objects.empty() ? nullptr : objects[which % objects.size()].get();
    }
    void act(FuzzObject& self, std::uint8_t action)
    {
        FuzzObject* other = pick(static_cast<std::uint8_t>(action >> 4));
        switch (action % 10)
        {
        case 0:
            break;
        case 1:
            if (other != nullptr)
                world.remove(*other);
            break;
        case 2:
            world.remove(self);
            break;
        case 3:
            if (other != nullptr)
                other->setAlive(!other->isAlive());
            break;
        case 4:
            if (other != nullptr)
                world.add(*other, 1, 0xFFFFFFFF,
                          (action & 0x20) != 0 ? hitbox::World::Shape::Circle
                                               : hitbox::World::Shape::Box);
            break;
        case 5:
            if (objects.size() < maxObjects)
            {
                objects.push_back(
                    std::make_unique<FuzzObject>(*this, bytes->next(), bytes->next()));
                world.add(*objects.back());
            }
            break;
        case 6:
            if (other != nullptr)
                objects[(action >> 4) % objects.size()].reset(); // destroys it, still in the World
            break;
        case 7:
            if (other != nullptr)
                other->setCollider(!other->isCollider());
            break;
        case 8:
            self.move({static_cast<float>(action >> 4) - 8.f, 0.f});
            break;
        default:
            for (std::unique_ptr<FuzzObject>& object : objects)
                if (object.get() == &self)
                    object.reset(); // destroys itself inside its own response: `self` is gone
            return;
        }
    }
};

void FuzzObject::collisionResponse(hitbox::GameObject*)
{
    scene.act(*this, action);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    Bytes bytes(data, size);
    Scene scene;
    scene.bytes = &bytes;
    scene.world.setMethod(static_cast<hitbox::BroadphaseMethod>(bytes.next() % 4));
    scene.world.setPushApart((bytes.next() & 1) != 0);
    const int count = 2 + bytes.next() % 15;
    for (int i = 0; i < count; ++i)
    {
        const std::uint8_t place = bytes.next();
        scene.objects.push_back(std::make_unique<FuzzObject>(scene, place, bytes.next()));
        scene.world.add(*scene.objects.back());
    }
    for (int pass = 0; pass < 6 && !bytes.empty(); ++pass)
    {
        scene.world.checkCollisions();
        const auto& found = scene.world.getCollisions();
        for (std::size_t x = 0; x < found.size(); ++x)
            for (std::size_t y = x + 1; y < found.size(); ++y)
                if (found[x] == found[y] && found[x].first != nullptr && found[x].second != nullptr)
                    std::abort(); // a pair reported twice in one pass
        // Between passes, one object does its action as if told of a collision.
        if (FuzzObject* chosen = scene.pick(bytes.next()))
            scene.act(*chosen, bytes.next());
    }
    scene.world.clear();
    for (const std::unique_ptr<FuzzObject>& object : scene.objects)
        if (object && object->inContacts != 0)
            std::abort(); // an Enter without its Exit
    return 0;
}
