#include "collision/pair_cache.hpp"

#include <utility>

namespace yardsim::collision {

namespace {

// (a, b) => one key
std::uint64_t pairKey(ObjectId a, ObjectId b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

// (key) => a well-mixed hash (splitmix64's finaliser)
std::uint64_t mix(std::uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ull;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

}  // namespace

// (table, key) => linear probing from the hash until the key or a stale slot
PairCache::Entry& PairCache::slot(Table& t, std::uint64_t key) {
  const std::size_t mask = t.slots.size() - 1;
  for (std::size_t i = mix(key) & mask;; i = (i + 1) & mask) {
    Entry& e = t.slots[i];
    if (e.stamp != t.stamp || e.key == key) return e;
  }
}

// (table) => rehashed into twice the slots (warm-up only: the tables keep their size)
void PairCache::grow(Table& t) {
  Table bigger;
  bigger.slots.assign(t.slots.empty() ? 1024 : 2 * t.slots.size(), Entry{});
  bigger.stamp = 1;
  for (Entry e : t.slots) {
    if (e.stamp != t.stamp || t.slots.empty()) continue;
    e.stamp = 1;
    slot(bigger, e.key) = e;
    ++bigger.used;
  }
  t = std::move(bigger);
}

// (contacts) => tables swapped, this query's emptied by a new stamp
void PairCache::begin(std::vector<Contact>& contacts) {
  std::swap(previous_, current_);
  std::swap(previousContacts_, contacts);
  contacts.clear();
  if (current_.slots.size() < previous_.slots.size())
    current_.slots.assign(previous_.slots.size(), Entry{});
  if (current_.slots.empty()) grow(current_);
  current_.used = 0;
  if (++current_.stamp == 0) {  // wrapped: wipe the slots once
    for (Entry& e : current_.slots) e.stamp = 0;
    current_.stamp = 1;
  }
}

// (pair, versions, limit, out) => last query's contacts when nothing changed
bool PairCache::reuse(ObjectId a, ObjectId b, std::uint64_t va, std::uint64_t vb, int maxPerPair,
                      std::vector<Contact>& out) {
  if (previous_.slots.empty()) return false;
  const std::uint64_t key = pairKey(a, b);
  const Entry& e = slot(previous_, key);
  if (e.stamp != previous_.stamp || e.key != key || e.va != va || e.vb != vb ||
      e.maxPerPair != maxPerPair) {
    return false;
  }
  const std::size_t first = out.size();
  out.insert(out.end(), previousContacts_.begin() + e.first,
             previousContacts_.begin() + e.first + e.count);
  record(a, b, va, vb, maxPerPair, first, e.count);
  return true;
}

// (pair, versions, limit, range) => this query's entry
void PairCache::record(ObjectId a, ObjectId b, std::uint64_t va, std::uint64_t vb, int maxPerPair,
                       std::size_t first, std::size_t count) {
  if (2 * (current_.used + 1) > current_.slots.size()) grow(current_);
  const std::uint64_t key = pairKey(a, b);
  Entry& e = slot(current_, key);
  if (e.stamp != current_.stamp) ++current_.used;
  e = {key,
       va,
       vb,
       static_cast<std::uint32_t>(first),
       static_cast<std::uint32_t>(count),
       current_.stamp,
       maxPerPair};
}

}  // namespace yardsim::collision
