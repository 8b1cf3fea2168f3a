#include "dressed_human/core/io/text_file.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

#include "temp_file_path.h"

namespace dressed_human {
namespace {

struct TestError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string messageOf(const std::string& path) {
  try {
    readWholeFileOrThrow<TestError>(path, "the test file");
  } catch (const TestError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(TextFile, ReadsEveryByteOfAFile) {
  const std::string path = tempFilePath("text_file_bytes.txt");
  const std::string bytes = std::string("line one\nline two\0with a NUL\r\n", 30);
  std::ofstream(path, std::ios::binary) << bytes;
  EXPECT_EQ(readWholeFileOrThrow<TestError>(path, "the test file"), bytes);
  std::remove(path.c_str());
}

TEST(TextFile, SaysWhyAFileCannotBeRead) {
  EXPECT_EQ(messageOf("/nonexistent/walk.yaml"),
            "/nonexistent/walk.yaml: cannot open the test file: No such file or directory");
  const std::string directory = testing::TempDir();
  EXPECT_EQ(messageOf(directory), directory + ": cannot open the test file: is a directory");
  if (geteuid() != 0) {  // root reads any file
    const std::string path = tempFilePath("text_file_unreadable.txt");
    std::ofstream(path) << "secret";
    chmod(path.c_str(), 0);
    EXPECT_EQ(messageOf(path), path + ": cannot open the test file: Permission denied");
    std::remove(path.c_str());
  }
}

}  // namespace
}  // namespace dressed_human
