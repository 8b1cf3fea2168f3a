#pragma once
// ctest runs each test in a process of its own, several at once: two tests writing one fixed name
// under TempDir() overwrite or delete each other's file. The process id keeps their paths apart.

#include <gtest/gtest.h>
#include <unistd.h>

#include <string>

namespace dressed_human {

inline std::string tempFilePath(const std::string& name) {
  return ::testing::TempDir() + "dressed_human_" + std::to_string(getpid()) + "_" + name;
}

}  // namespace dressed_human
