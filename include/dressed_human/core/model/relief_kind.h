#pragma once
// What a drawn part's relief is (the skin's cells or the cloth's wrinkles), and a value kept per
// kind, indexed by the kind itself rather than by a hand-written 0 or 1.

#include <array>
#include <cstddef>
#include <utility>

namespace dressed_human {

enum class ReliefKind { kSkin, kCloth };

template <typename T>
class PerReliefKind {
 public:
  PerReliefKind() = default;
  PerReliefKind(T skin, T cloth) : values_{{std::move(skin), std::move(cloth)}} {}
  T& operator[](ReliefKind kind) { return values_[static_cast<std::size_t>(kind)]; }
  const T& operator[](ReliefKind kind) const { return values_[static_cast<std::size_t>(kind)]; }
  auto begin() { return values_.begin(); }
  auto end() { return values_.end(); }
  auto begin() const { return values_.begin(); }
  auto end() const { return values_.end(); }

 private:
  std::array<T, 2> values_{};
};

}  // namespace dressed_human
