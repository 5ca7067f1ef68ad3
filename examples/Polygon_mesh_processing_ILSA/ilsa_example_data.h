// Where the examples find a bundled mesh when no file is given: in the
// directory named by the environment variable ILSA_DATA_DIR, else in
// data/meshes/ below the current directory or one of its three parents (a
// checkout, or a build directory inside it). Resolved at run time.
#ifndef ILSA_EXAMPLE_DATA_H
#define ILSA_EXAMPLE_DATA_H

#include <cstdlib>
#include <fstream>
#include <string>

inline std::string ilsa_data_file(const std::string& name) {
  if (const char* dir = std::getenv("ILSA_DATA_DIR")) return std::string(dir) + "/" + name;
  std::string up;
  for (int level = 0; level < 4; ++level, up += "../")
    if (std::ifstream(up + "data/meshes/" + name)) return up + "data/meshes/" + name;
  return "data/meshes/" + name; // not found: the caller reports it unreadable
}

#endif
