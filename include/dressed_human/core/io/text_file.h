#pragma once
// Whole-file reading for the loaders (motions, bodies, garments, joint maps, URDF, BVH, .mot):
// one place that opens a file and says why it could not.

#include <string>

namespace dressed_human {

// The file's bytes into `text`; false with the reason in `why` ("No such file or directory",
// "is a directory", ...) when it cannot be read.
bool readWholeFile(const std::string& path, std::string& text, std::string& why);

// The file's bytes; throws Error("<path>: cannot open <what>: <why>") when it cannot be read.
template <typename Error>
std::string readWholeFileOrThrow(const std::string& path, const std::string& what) {
  std::string text, why;
  if (!readWholeFile(path, text, why)) throw Error(path + ": cannot open " + what + ": " + why);
  return text;
}

}  // namespace dressed_human
