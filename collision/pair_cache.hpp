#pragma once
// The last contact query's narrow-phase results per pair, reused when neither object has moved
// since: two static parts (a block on its supports while nothing touches it, a container stack)
// give the same contacts as last step, bit for bit, so only pairs with a moved object go through
// FCL again. An object's version counts its pose updates; a pair's entry holds the versions it
// was computed at, the contact limit and its range of contacts. Two open-addressing tables (last
// query's and this one's) swapped per query: no allocation once they have grown to the pair count.
#include <cstdint>
#include <vector>

#include "collision/collision_world.hpp"

namespace yardsim::collision {

class PairCache {
 public:
  // (contacts vector of the world) => starts a query: last query's table and contacts kept for
  // lookups (contacts is emptied), this query's table emptied
  void begin(std::vector<Contact>& contacts);
  // (a < b, their versions, contact limit, out) => whether last query had the pair at these
  // versions and limit; if so its contacts are appended to out and the pair recorded again
  bool reuse(ObjectId a, ObjectId b, std::uint64_t va, std::uint64_t vb, int maxPerPair,
             std::vector<Contact>& out);
  // (a < b, versions, limit, first contact index in out, count) => recorded for the next query
  void record(ObjectId a, ObjectId b, std::uint64_t va, std::uint64_t vb, int maxPerPair,
              std::size_t first, std::size_t count);

 private:
  struct Entry {
    std::uint64_t key = 0;  // (a << 32) | b
    std::uint64_t va = 0, vb = 0;
    std::uint32_t first = 0, count = 0;
    std::uint32_t stamp = 0;  // valid when equal to its table's stamp
    int maxPerPair = 0;
  };
  struct Table {
    std::vector<Entry> slots;  // size a power of two, at most half full
    std::uint32_t stamp = 0;
    std::size_t used = 0;
  };
  // (table, key) => the slot holding key or the empty slot where it goes
  static Entry& slot(Table& t, std::uint64_t key);
  // (table) => twice the slots, its valid entries moved over
  static void grow(Table& t);

  Table previous_, current_;
  std::vector<Contact> previousContacts_;
};

}  // namespace yardsim::collision
