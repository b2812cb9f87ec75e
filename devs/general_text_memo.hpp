#pragma once
// printf's "%g" text of doubles that are written again and again through numbered slots (the
// coordinates of a state in every trace record): each slot keeps its last value's bits and text.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace yardsim::devs {

class General6Memo {
 public:
  // (slot, number) => appendGeneral6(out, value): the slot's kept text when value has the same
  // bits as the last number written through it, else formatted and kept. Slots are made on first
  // use (no allocation once every slot has been used)
  void append(std::string& out, std::size_t slot, double value);

 private:
  struct Entry {
    std::uint64_t bits = 0;
    std::uint8_t size = 0;  // 0: nothing kept yet (no "%g" text is empty)
    char text[15] = {};     // the longest "%g" text, "-1.23457e-308", has 13 characters
  };
  std::vector<Entry> entries_;
};

}  // namespace yardsim::devs
