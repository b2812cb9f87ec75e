#pragma once
// Blocks and their lugs in the database: checked on the way in (mass, inertia, lugs, a name not
// yet taken), read back whole.
#include <optional>
#include <string>
#include <vector>

#include "yard/database.hpp"
#include "yard/records.hpp"

namespace yardsim::yard {

// (database opened for writing, block) => the block and its lugs stored in one transaction;
// DatabaseError for a duplicate name, a bad mass or inertia, a lug with swl <= 0 or no direction
void insertBlock(const Database& db, const Block& block);
// (database, name) => the block with its lugs and mesh, or nothing
std::optional<Block> findBlock(const Database& db, const std::string& name);
// (database, name) => the block; DatabaseError naming the blocks there are when it is missing
Block getBlock(const Database& db, const std::string& name);
// (database) => every block's name, sorted
std::vector<std::string> blockNames(const Database& db);

// (known names, what, name) => "unknown <what> 'name' (the <what>s are a, b, c)"
std::string unknownName(const std::vector<std::string>& known, const std::string& what,
                        const std::string& name);

}  // namespace yardsim::yard
