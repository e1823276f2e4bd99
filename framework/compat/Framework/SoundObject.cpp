#include "Framework/SoundObject.h"

SoundObject::SoundObject() = default;

SoundObject::~SoundObject() = default;

void SoundObject::loadSound(std::string filename, std::string lname)
{
    name = lname;
    if (buffer.loadFromFile(filename))
        sound.setBuffer(buffer);
}
