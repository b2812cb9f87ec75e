#include "devs/general_text_memo.hpp"

#include <cstring>

#include "devs/general_text.hpp"

namespace yardsim::devs {

void General6Memo::append(std::string& out, std::size_t slot, double value) {
  // (slot's last bits and text, value) => the kept text, or a fresh one kept for the next call
  std::uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  if (slot >= entries_.size()) entries_.resize(slot + 1);
  Entry& e = entries_[slot];
  if (e.size != 0 && e.bits == bits) {
    out.append(e.text, e.size);
    return;
  }
  const std::size_t start = out.size();
  appendGeneral6(out, value);
  const std::size_t n = out.size() - start;
  if (n == 0 || n > sizeof e.text) {  // not kept (no such text today)
    e.size = 0;
    return;
  }
  std::memcpy(e.text, out.data() + start, n);
  e.size = static_cast<std::uint8_t>(n);
  e.bits = bits;
}

}  // namespace yardsim::devs
