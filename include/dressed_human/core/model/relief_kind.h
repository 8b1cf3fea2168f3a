#pragma once
// What a drawn part's relief is (the skin's cells or the cloth's wrinkles), and a value kept per
// kind, indexed by the kind itself rather than by a hand-written 0 or 1.
//
// The words, one per idea, as the code and the README use them: *skin* and *cloth* are the two
// kinds (a garment's surface is cloth). The skin's relief is its *cells* (Voronoi cells bounded
// by furrows). The cloth's relief is its *wrinkles*: the buckling pattern of the seed paper,
// placed where the garment is compressed (wrinkle map, wrinkle strength, wrinkle placement). A
// *fold* is one ridge of the wrinkles (fold axis: which way it runs; fold width; fold softness;
// fold tiles: the ridges' profiles the shader orients).

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
