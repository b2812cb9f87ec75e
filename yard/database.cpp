#include "yard/database.hpp"

#include <sqlite3.h>

#include <filesystem>

#include "yard/schema.hpp"

namespace yardsim::yard {

struct Database::Handle {
  sqlite3* db = nullptr;
  ~Handle() { sqlite3_close_v2(db); }
};

namespace {

// (handle, SQL, values) => the statement prepared and bound; throws with SQLite's message
sqlite3_stmt* prepare(sqlite3* db, const std::string& path, const std::string& sql,
                      const Row& values) {
  sqlite3_stmt* st = nullptr;
  if (sqlite3_prepare_v2(db, sql.c_str(), -1, &st, nullptr) != SQLITE_OK)
    throw DatabaseError(path + ": " + sqlite3_errmsg(db));
  for (std::size_t i = 0; i < values.size(); ++i) {
    const int k = static_cast<int>(i) + 1;
    const Value& v = values[i];
    int rc = SQLITE_OK;
    if (std::holds_alternative<std::monostate>(v))
      rc = sqlite3_bind_null(st, k);
    else if (const auto* n = std::get_if<std::int64_t>(&v))
      rc = sqlite3_bind_int64(st, k, *n);
    else if (const auto* x = std::get_if<double>(&v))
      rc = sqlite3_bind_double(st, k, *x);
    else if (const auto* s = std::get_if<std::string>(&v))
      rc = sqlite3_bind_text(st, k, s->c_str(), static_cast<int>(s->size()), SQLITE_TRANSIENT);
    else {
      const auto& b = std::get<std::vector<unsigned char>>(v);
      rc = sqlite3_bind_blob(st, k, b.data(), static_cast<int>(b.size()), SQLITE_TRANSIENT);
    }
    if (rc != SQLITE_OK) {
      sqlite3_finalize(st);
      throw DatabaseError(path + ": " + sqlite3_errmsg(db));
    }
  }
  return st;
}

// (statement at a row) => the row's values
Row readRow(sqlite3_stmt* st) {
  Row row;
  for (int c = 0; c < sqlite3_column_count(st); ++c) {
    switch (sqlite3_column_type(st, c)) {
      case SQLITE_INTEGER:
        row.emplace_back(static_cast<std::int64_t>(sqlite3_column_int64(st, c)));
        break;
      case SQLITE_FLOAT:
        row.emplace_back(sqlite3_column_double(st, c));
        break;
      case SQLITE_TEXT:
        row.emplace_back(std::string(reinterpret_cast<const char*>(sqlite3_column_text(st, c)),
                                     static_cast<std::size_t>(sqlite3_column_bytes(st, c))));
        break;
      case SQLITE_BLOB: {
        const auto* p = static_cast<const unsigned char*>(sqlite3_column_blob(st, c));
        row.emplace_back(std::vector<unsigned char>(p, p + sqlite3_column_bytes(st, c)));
        break;
      }
      default:
        row.emplace_back(std::monostate{});
    }
  }
  return row;
}

// (path, flags) => an open connection with foreign keys on and a busy timeout for shared use
std::unique_ptr<Database::Handle> connect(const std::string& path, int flags);

}  // namespace

Database::Database(std::unique_ptr<Handle> handle, std::string path)
    : handle_(std::move(handle)), path_(std::move(path)) {}
Database::Database(Database&&) noexcept = default;
Database& Database::operator=(Database&&) noexcept = default;
Database::~Database() = default;

std::vector<Row> Database::query(const std::string& sql, const Row& values) const {
  sqlite3_stmt* st = prepare(handle_->db, path_, sql, values);
  std::vector<Row> rows;
  int rc = 0;
  while ((rc = sqlite3_step(st)) == SQLITE_ROW) rows.push_back(readRow(st));
  const std::string message = rc == SQLITE_DONE ? "" : sqlite3_errmsg(handle_->db);
  sqlite3_finalize(st);
  if (!message.empty()) throw DatabaseError(path_ + ": " + message);
  return rows;
}

void Database::execute(const std::string& sql, const Row& values) const {
  query(sql, values);
}

void Database::script(const std::string& sql) const {
  char* error = nullptr;
  if (sqlite3_exec(handle_->db, sql.c_str(), nullptr, nullptr, &error) != SQLITE_OK) {
    const std::string message = error ? error : sqlite3_errmsg(handle_->db);
    sqlite3_free(error);
    throw DatabaseError(path_ + ": " + message);
  }
}

void Database::transaction(const std::function<void()>& work) const {
  execute("BEGIN IMMEDIATE");
  try {
    work();
    execute("COMMIT");
  } catch (...) {
    sqlite3_exec(handle_->db, "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
}

int Database::schemaVersion() const {
  return static_cast<int>(asNumber(query("PRAGMA user_version").at(0).at(0)));
}

namespace {

std::unique_ptr<Database::Handle> connect(const std::string& path, int flags) {
  auto h = std::make_unique<Database::Handle>();
  if (sqlite3_open_v2(path.c_str(), &h->db, flags, nullptr) != SQLITE_OK)
    throw DatabaseError(
        path + ": cannot open the database: " + (h->db ? sqlite3_errmsg(h->db) : "out of memory"));
  sqlite3_busy_timeout(h->db, 5000);
  sqlite3_exec(h->db, "PRAGMA foreign_keys = ON", nullptr, nullptr, nullptr);
  return h;
}

// (database) => nothing, or DatabaseError: not SQLite, damaged, another program's, or newer
void checkOurs(const Database& db, bool allowOlder) {
  const std::string& path = db.path();
  std::int64_t app = 0;
  try {
    app = static_cast<std::int64_t>(asNumber(db.query("PRAGMA application_id").at(0).at(0)));
    const auto check = db.query("PRAGMA quick_check");
    if (check.empty() || asText(check[0][0]) != "ok")
      throw DatabaseError(path + ": " +
                          (check.empty() ? std::string("no answer") : asText(check[0][0])));
  } catch (const DatabaseError& e) {
    throw DatabaseError(path +
                        ": not a readable yardsim database (damaged or not SQLite): " + e.what());
  }
  if (app != kApplicationId) {
    const bool empty = db.query("SELECT 1 FROM sqlite_schema LIMIT 1").empty();
    throw DatabaseError(path +
                        (empty ? ": an empty SQLite file, not a yardsim database (make one with "
                                 "yardsim db init)"
                               : ": another program's SQLite database (its application_id is " +
                                     std::to_string(app) + ", not yardsim's)"));
  }
  const int v = db.schemaVersion();
  if (v > kSchemaVersion)
    throw DatabaseError(path + ": schema version " + std::to_string(v) +
                        " was written by a newer yardsim (this one "
                        "reads up to " +
                        std::to_string(kSchemaVersion) + ")");
  if (v < kSchemaVersion && !allowOlder)
    throw DatabaseError(path + ": schema version " + std::to_string(v) + " is older than " +
                        std::to_string(kSchemaVersion) + "; migrate it with yardsim db init " +
                        path);
}

// (database at version v) => every later migration applied, user_version set, in one transaction
void migrate(const Database& db) {
  const int from = db.schemaVersion();
  if (from == kSchemaVersion) return;
  db.transaction([&] {
    for (int k = from; k < kSchemaVersion; ++k)
      db.script(migrations()[static_cast<std::size_t>(k)]);
    db.execute("PRAGMA user_version = " + std::to_string(kSchemaVersion));
  });
}

}  // namespace

Database Database::create(const std::string& path) {
  if (std::filesystem::exists(path))
    throw DatabaseError(path + ": already exists (yardsim db init makes a new database)");
  Database db(connect(path, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE), path);
  db.execute("PRAGMA application_id = " + std::to_string(kApplicationId));
  migrate(db);
  return db;
}

Database Database::openReadOnly(const std::string& path) {
  if (!std::filesystem::is_regular_file(path))
    throw DatabaseError(path + ": no such database file");
  Database db(connect(path, SQLITE_OPEN_READONLY), path);
  checkOurs(db, false);
  return db;
}

Database Database::openForWriting(const std::string& path) {
  if (!std::filesystem::is_regular_file(path))
    throw DatabaseError(path + ": no such database file (yardsim db init " + path + " makes one)");
  Database db(connect(path, SQLITE_OPEN_READWRITE), path);
  checkOurs(db, true);
  migrate(db);
  return db;
}

double asNumber(const Value& v) {
  if (const auto* n = std::get_if<std::int64_t>(&v)) return static_cast<double>(*n);
  if (const auto* x = std::get_if<double>(&v)) return *x;
  throw DatabaseError("expected a number in the database, found another type");
}

std::string asText(const Value& v) {
  if (const auto* s = std::get_if<std::string>(&v)) return *s;
  if (isNull(v)) return "";
  throw DatabaseError("expected text in the database, found another type");
}

const std::vector<unsigned char>& asBlob(const Value& v) {
  if (const auto* b = std::get_if<std::vector<unsigned char>>(&v)) return *b;
  throw DatabaseError("expected a blob in the database, found another type");
}

}  // namespace yardsim::yard
