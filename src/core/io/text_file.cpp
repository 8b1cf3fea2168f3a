#include "dressed_human/core/io/text_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace dressed_human {

bool readWholeFile(const std::string& path, std::string& text, std::string& why) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) {
    why = std::strerror(errno);
    return false;
  }
  // An ifstream "opens" a directory on Linux and then reads nothing: say what it is instead.
  if (S_ISDIR(status.st_mode)) {
    why = "is a directory";
    return false;
  }
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    why = std::strerror(errno);
    return false;
  }
  std::stringstream contents;
  contents << file.rdbuf();
  if (file.bad()) {
    why = "read error";
    return false;
  }
  text = contents.str();
  return true;
}

}  // namespace dressed_human
