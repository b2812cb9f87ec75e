#pragma once
// A block written out of the database: DIR/NAME.yaml (a body fragment with its figures and lugs,
// SI units, block frame) and, when it has one, DIR/NAME.obj (its mesh, exact to 17 digits).
#include <string>

#include "yard/records.hpp"

namespace yardsim::yard {

// (block, folder) => the YAML file's path; the folder created; DatabaseError if it cannot write
std::string exportBlock(const Block& block, const std::string& dir);
// (block) => the YAML text exportBlock writes (mesh: NAME.obj when the block has a mesh)
std::string blockYaml(const Block& block);

}  // namespace yardsim::yard
