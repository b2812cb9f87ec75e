#pragma once
// The database's schema as migrations: migration k (1-based) takes a database at user_version
// k - 1 to k. A new version appends one migration; none is ever edited once released.
#include <string>
#include <vector>

namespace yardsim::yard {

// () => the SQL of each migration in order; kSchemaVersion == migrations().size()
const std::vector<std::string>& migrations();

}  // namespace yardsim::yard
