// Included before every file of a course lab (never before Hitbox's own code).
//
// Visual Studio's standard headers include one another far more than g++'s do, so lab code
// that compiles there often calls std::sqrt, pow or abs without <cmath>, or uses
// std::string, std::vector or std::cout without including them. These are the headers such
// code leans on; a lab that includes them itself loses nothing.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>
