#pragma once
// The yard's database: one SQLite file (no server) with a versioned schema (PRAGMA user_version,
// migrations applied in order by `create`/`openForWriting`) marked as ours by PRAGMA
// application_id. Runs open it read-only, so many may share it; every write is one transaction.
// A file that is not SQLite, is another program's database, or was made by a newer yardsim is
// refused with a DatabaseError naming the file. No SQLite type appears here.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace yardsim::yard {

// A user error: a bad file, a duplicate or unknown name, a value out of range. The message names
// the database file and what was expected.
class DatabaseError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One SQL value: NULL, an integer, a real, text or a blob.
using Value =
    std::variant<std::monostate, std::int64_t, double, std::string, std::vector<unsigned char>>;
using Row = std::vector<Value>;

// ('Y','A','R','D') as PRAGMA application_id; the schema version this build writes
inline constexpr std::int32_t kApplicationId = 0x59415244;
inline constexpr int kSchemaVersion = 1;

class Database {
 public:
  // (path) => a new database with the current schema; DatabaseError if the file exists
  static Database create(const std::string& path);
  // (path) => the database opened read-only (what runs use), checked as ours and current
  static Database openReadOnly(const std::string& path);
  // (path) => the database opened for writing, older schemas migrated in one transaction
  static Database openForWriting(const std::string& path);

  Database(Database&&) noexcept;
  Database& operator=(Database&&) noexcept;
  ~Database();

  // (SQL with ? placeholders, values) => the rows it returns (none for a statement)
  std::vector<Row> query(const std::string& sql, const Row& values = {}) const;
  // (SQL, values) => nothing; executes one statement
  void execute(const std::string& sql, const Row& values = {}) const;
  // (SQL of several statements, no values) => nothing; executes them in order
  void script(const std::string& sql) const;
  // (work) => work done inside BEGIN IMMEDIATE .. COMMIT, rolled back if it throws
  void transaction(const std::function<void()>& work) const;

  const std::string& path() const { return path_; }
  int schemaVersion() const;

  struct Handle;  // the SQLite connection, opaque here

 private:
  Database(std::unique_ptr<Handle> handle, std::string path);
  std::unique_ptr<Handle> handle_;
  std::string path_;
};

// (value) => its number (an integer or real), text, or blob; DatabaseError if it is another type
double asNumber(const Value& v);
std::string asText(const Value& v);
const std::vector<unsigned char>& asBlob(const Value& v);
// (value) => whether it is NULL
inline bool isNull(const Value& v) {
  return std::holds_alternative<std::monostate>(v);
}

}  // namespace yardsim::yard
