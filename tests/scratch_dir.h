#pragma once
// A test fixture with a fresh, empty folder per test (named after the process, the suite and the
// test, so parallel ctest runs never share one), removed afterwards.

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

namespace meshprep::test {

class ScratchDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string("meshprep-") + info->test_suite_name() + "-" + info->name() + "-" +
                       std::to_string(::getpid());
    std::replace(name.begin(), name.end(), '/', '-');  // parameterised tests
    dir_ = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  /// The path of `name` in the test's folder.
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  /// Writes `content` (text or bytes) to `name` in the test's folder and returns its path.
  std::string file(const std::string& name, const std::string& content) const {
    std::ofstream out(path(name), std::ios::binary);
    out << content;
    return path(name);
  }

  std::filesystem::path dir_;
};

}  // namespace meshprep::test
