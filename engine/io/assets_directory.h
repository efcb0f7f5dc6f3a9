// Where the shipped assets (tables/, balls/, scenes/) are at run time. Nothing is compiled in, so
// an installed prefix can be moved: the folder is the environment variable BAIZE_DATA_DIR when it
// is set, else the nearest share/baize/ above the program or Python module that holds this code
// (P/bin/baize finds P/share/baize, a module in P/lib/python3/dist-packages/baize/ finds it too,
// and programs in a build tree find the build tree's share/baize, a link to the source assets).
#pragma once

#include <string>

namespace baize::engine {

// The environment variable that names the assets folder, overriding the search.
inline constexpr const char* kDataDirectoryVariable = "BAIZE_DATA_DIR";

// The assets folder, found once per process. Throws std::runtime_error naming the places looked
// at and the variable to set when there is none.
std::string assetsDirectory();

// The search itself, from the folder `start` (a program's or module's folder) upwards: the first
// `<folder>/share/baize` holding tables/, or "" when none within a few levels.
std::string assetsDirectoryAbove(const std::string& start);

}  // namespace baize::engine
