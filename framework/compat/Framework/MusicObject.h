// Framework/MusicObject.h - a named music file for the course's AudioManager. Music
// streams from its file while it plays, so only the file name is kept here.
#pragma once

#include <string>

class MusicObject
{
public:
    MusicObject();
    ~MusicObject();

    void setMusic(std::string lfilename, std::string lname);

    std::string filename;
    std::string name;
};
