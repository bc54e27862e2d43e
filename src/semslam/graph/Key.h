#pragma once
// Typed variable keys.
//
// A Key is a 64-bit integer: the top 8 bits hold a character naming the kind of variable ('x' robot pose,
// 'l' landmark, 'o' object, ...), the low 56 bits its index. A key whose character is 0 is a plain number, as the
// ids of a g2o file are; it prints as that number, a typed key prints as its character and index ("x12", "l3").

#include <cstdint>
#include <string>

namespace semslam {

using Key = std::uint64_t;

class Symbol {
 public:
  static constexpr int kIndexBits = 56;
  static constexpr std::uint64_t kIndexMask = (std::uint64_t{1} << kIndexBits) - 1;

  constexpr Symbol(char tag, std::uint64_t index) : tag_(tag), index_(index) {}
  /// Decomposes a key into its character and index.
  constexpr explicit Symbol(Key key)
      : tag_(static_cast<char>(key >> kIndexBits)), index_(key & kIndexMask) {}

  constexpr char tag() const { return tag_; }
  constexpr std::uint64_t index() const { return index_; }
  constexpr Key key() const {
    return (static_cast<std::uint64_t>(static_cast<unsigned char>(tag_)) << kIndexBits) | (index_ & kIndexMask);
  }
  constexpr operator Key() const { return key(); }  // NOLINT: a Symbol is used wherever a Key is expected

 private:
  char tag_;
  std::uint64_t index_;
};

/// Shorthands for the usual variable kinds.
constexpr Key poseKey(std::uint64_t index) { return Symbol('x', index); }
constexpr Key landmarkKey(std::uint64_t index) { return Symbol('l', index); }

/// "x12" for a typed key, "12" for a plain one.
std::string keyToString(Key key);

/// Inverse of keyToString: "x12" -> Symbol('x', 12), "12" -> 12. Throws std::invalid_argument on anything else.
Key keyFromString(const std::string& text);

}  // namespace semslam
