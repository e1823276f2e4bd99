#include "Framework/MusicObject.h"

MusicObject::MusicObject() = default;

MusicObject::~MusicObject() = default;

void MusicObject::setMusic(std::string lfilename, std::string lname)
{
    filename = lfilename;
    name = lname;
}
